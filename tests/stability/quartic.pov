// quartic.pov: an ill-conditioned quartic: the torus of thin-torus.pov
// (R = 100, r = 0.1), same view, written as a quartic (run.sh:
// quartic-literal, quartic-scaled, quartic-exact). The torus is
//   (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) = 0.
// FORM = 1: with R = 100, r = 0.1 written in: the coefficients run from 1
// (x^4) through -20000.02 (x^2) to 99999800.0001 (the constant), eight
// orders of magnitude, and the surface is a thin tube where the
// polynomial is a tiny difference of large terms.
// FORM = 2: R = 1, r = 0.001 (constant (1 - 1e-6)^2), then scale 100.
// Declare=STURM=1 adds sturm.
//
// Properties: (1) each form's image equals the torus primitive's
// (thin-torus.pov) up to 2 pixels over 1/255: same pixels, same shading;
// (2) exact, as for thin-torus.pov (check.py torus).
//
// lucent passes, both forms, with and without sturm: identical to the
// torus primitive. POV-Ray 3.7 too (identical as well).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (FORM) #declare FORM = 1; #end
#ifndef (STURM) #declare STURM = 0; #end

camera {
  location <0, 20, -120>
  direction <0, -0.25, 1>*0.45
  right x*image_width/image_height
  up <0, 1, 0.25>
}
light_source { <30, 200, -100> color rgb 1 }
background { color rgb <0.05, 0.05, 0.15> }

// torus_quartic(R, r): the 35 coefficients of the torus above, in
// POV-Ray's order (x^4, x^3y, ..., constant).
#macro Torus_quartic(R, r)
  #local A = R*R - r*r;
  <1, 0, 0, 0, 2, 0, 0, 2, 0, 2*A - 4*R*R,
   0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
   1, 0, 0, 2, 0, 2*A, 0, 0, 0, 0,
   1, 0, 2*A - 4*R*R, 0, A*A>
#end

quartic {
  #switch (FORM)
    #case (1) Torus_quartic(100, 0.1) #break
    #else Torus_quartic(1, 0.001) scale 100
  #end
  #if (STURM) sturm #end
  pigment { color rgb <1, 0.85, 0.4> } finish { ambient 0.3 diffuse 0.7 }
}
