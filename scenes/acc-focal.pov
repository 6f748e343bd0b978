// Accuracy sweep (tests/bench/accuracy.sh): focal blur across a row of
// spheres at increasing distance, focused on the middle one. The sweep
// sets the lens sampling through declares (defaults in brackets):
//   BS    blur_samples (the maximum) [24]
//   BVAR  variance [1/128]
//   BCONF confidence [0.9]
#version 3.7;
#ifndef (BS) #declare BS = 24; #end
#ifndef (BVAR) #declare BVAR = 1/128; #end
#ifndef (BCONF) #declare BCONF = 0.9; #end
global_settings { assumed_gamma 1 }
camera {
  location <0,1.5,-6> look_at <0,0.8,2> angle 45
  aperture 0.6 focal_point <0,0.8,1> blur_samples BS variance BVAR confidence BCONF
}
light_source { <-5,8,-6>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.15 rgb 0.9 scale 0.5 } finish { ambient 0.15 diffuse 0.8 } }
#declare I = 0;
#while (I < 5)
  sphere { <-2.4 + I*1.2, 0.5, -2 + I*1.5>, 0.5
    pigment { rgb <1 - I/5, 0.3 + I/8, I/5> } finish { ambient 0.1 diffuse 0.8 phong 0.6 } }
  #declare I = I + 1;
#end
