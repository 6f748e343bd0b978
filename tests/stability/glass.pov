// glass.pov: clear glass in a uniform surround, a "furnace" whose every
// pixel is known (run.sh: glass-tir, glass-depth-*, glass-depth-povray,
// glass-fresnel-*). Nothing is lit: the background is the only light,
// and the glass neither absorbs nor scatters, so every ray that gets out
// carries the background colour BG exactly. Two groups:
//   - left, a cube of ior 1.5 turned on two axes: inside it most rays meet
//     a face beyond the critical angle (41.8 degrees) and are totally
//     reflected, some many times (one pixel needs more than 128 levels);
//   - right, nested glass: a cube of ior 1.5 holding a sphere of ior 2.0
//     that holds an air bubble (ior 1.0), so each crossing bends by the
//     ratio of the two media it separates.
// Declare=L=N sets max_trace_level (default 256).
//
// Clear glass (FRESNEL=0: transmit 1, no reflection): each pixel follows
// one path of refractions and total internal reflections, each using a
// trace level. Properties: (1) with L = 256 every pixel is BG within
// 2e-3 (OpenEXR): total internal reflection loses nothing, no NaN, no
// black; (2) with L = 3, 6 and 64 every pixel is BG or black (black where
// the path is longer than L, as the manual says of max_trace_level), and
// a pixel black at one L is black at every lower L; (3) the black pixels
// at L = 6 are POV-Ray's (tests/stability/povray/glass-depth6.png), which
// checks the nested paths, up to 0 pixels.
// lucent passes all three; POV-Ray 3.7 passes (1) and (2) too, with the
// same black pixels at every L tried: 4745 at L = 3, 1352 at 6, 1 at 64
// and 128, none at 256.
//
// Fresnel glass (FRESNEL=1: reflection { 0, 1 fresnel on } and
// conserve_energy, L = 64): every crossing splits into a reflected and a
// transmitted ray whose weights add up to 1, so the image is BG again,
// less what adaptive depth control drops: a ray whose weight falls under
// adc_bailout (default 1/255) is not traced, and many dropped rays add
// up. Properties: (4) no channel above BG by more than 2e-3 (light is never
// created), no NaN, mean loss under 1%; (5) with adc_bailout 1e-3 (ADC=1e-3) no
// pixel darker than with the default (so the loss is ADC's).
// lucent passes both: mean loss 0.33% (0.12% at 1e-3), worst pixel
// 0.896 of BG. POV-Ray 3.7 passes both: mean loss 0.16% (0.04%), worst
// pixel 0.787 of BG.
#version 3.7;
#ifndef (L) #declare L = 256; #end
#ifndef (FRESNEL) #declare FRESNEL = 0; #end
#ifndef (ADC) #declare ADC = 1/255; #end
#declare BG = <1, 0.6, 0.3>;
global_settings { assumed_gamma 1.0 max_trace_level L adc_bailout ADC }
camera {
  location <0, 0, -10>
  look_at <0, 0, 0>
  right x*image_width/image_height
  angle 40
}
background { rgb BG }

#declare Glass = material {
  texture {
    pigment { rgbt 1 }
    finish {
      ambient 0 diffuse 0 specular 0
      #if (FRESNEL) reflection { 0, 1 fresnel on } conserve_energy #end
    }
  }
  interior { ior 1.5 }
}
// total internal reflection
box { -1, 1 material { Glass } rotate <30, 40, 0> translate <-2.2, 0, 0> }
// nested glass
box { -1, 1 material { Glass } rotate <10, -20, 0> translate <1.6, 0, 0> }
sphere { <1.6, 0, 0>, 0.8 material { Glass interior { ior 2.0 } } }
sphere { <1.6, 0, 0>, 0.4 material { Glass interior { ior 1.0 } } }
