// nested.pov: glass nested in glass of the same index (run.sh: nested).
// A cube of ior 1.5 holds a sphere of ior 1.5, which holds (off centre) a
// smaller one of ior 1.5; a sphere of ior 1.33 holds an off-centre one of
// ior 1.33. The inner spheres are perfectly clear (transmit 1, no
// reflection, no highlight), so crossing into them changes nothing: the
// ray goes from a medium into the same medium, and must not bend. A
// renderer that takes an inner sphere's ior as relative to air, or loses
// track of which medium the ray is in when it leaves an inner sphere,
// bends it. The outer objects are a tinted, slightly reflective glass
// (the textures of every object are the same as without the inner
// spheres), in front of checkered walls.
// Declare=REF=1 leaves the inner spheres out.
//
// Property: the image equals the REF image up to 0 pixels over 1/255.
// lucent passes (identical). POV-Ray 3.7 passes (identical).
// (The two renderers' images differ from each other on 11.5% of the
// pixels, max 0.043: the tinted, reflective outer glass, the difference
// of scenes/acc-glass.pov, not this property.)
#version 3.7;
#ifndef (REF) #declare REF = 0; #end
global_settings { assumed_gamma 1.0 max_trace_level 20 }
camera {
  location <0, 2, -8>
  look_at <0, 0.3, 0>
  right x*image_width/image_height
  angle 45
}
light_source { <-5, 8, -6> color rgb 1 }
plane {
  z, 4
  pigment { checker rgb <0.9, 0.85, 0.7> rgb <0.2, 0.3, 0.5> scale 0.5 }
  finish { ambient 0.3 diffuse 0.7 }
}
plane {
  y, -1.2
  pigment { checker rgb <0.9, 0.3, 0.2> rgb 0.9 scale 0.5 }
  finish { ambient 0.3 diffuse 0.7 }
}
#declare Tinted = texture {
  pigment { rgbf <0.95, 1, 0.9, 1> }
  finish { ambient 0 diffuse 0 specular 0.4 roughness 0.01 reflection { 0.05 } }
}
#declare Clear = texture {
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 specular 0 }
}
box { -1, 1 texture { Tinted } interior { ior 1.5 } rotate <0, 25, 0> translate <-1.6, 0, 0> }
sphere { <1.5, 0, 0>, 1.1 texture { Tinted } interior { ior 1.33 } }
#if (!REF)
  sphere { <-1.6, 0, 0>, 0.6 texture { Clear } interior { ior 1.5 } }
  sphere { <-1.6, 0.3, 0>, 0.25 texture { Clear } interior { ior 1.5 } }
  sphere { <1.4, 0.2, -0.3>, 0.5 texture { Clear } interior { ior 1.33 } }
#end
