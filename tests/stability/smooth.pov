// smooth.pov: a coarse sphere mesh of smooth triangles, lit from the side
// (run.sh: smooth-shadow, smooth-bumps-shadow): POV-Ray's shadow-line
// artifact. The mesh (12 x 8 facets) carries the true sphere's normals at
// its vertices, so its shading falls off smoothly to the terminator where
// the interpolated normal turns away from the light. But near that line a
// facet's own plane already faces away from the light: a shadow ray from
// there starts into the solid and meets the mesh's far side, and the
// point is shadowed although its shading normal says lit. The shadow edge
// then follows the facets (the mesh's silhouette seen from the light), a
// hard, polygonal line across the smooth gradient. With Declare=BUMPS=1
// the normals are perturbed further by bumps.
// Declare=NOSHADOW=1 makes the mesh no_shadow: as a convex object it has
// nothing else to shadow, so that image is the smooth shading alone.
//
// Property: the image equals the NOSHADOW image up to 4 pixels over 0.1.
// Both renderers FAIL it, in the same way (the artifact is the same; both
// are XFAIL in run.sh): without bumps lucent 598 pixels over 0.1 (max
// 0.60), POV-Ray 3.7 594 (max 0.60); with bumps lucent 496, POV-Ray 740
// (max 0.62 both).
#version 3.7;
#ifndef (NOSHADOW) #declare NOSHADOW = 0; #end
#ifndef (BUMPS) #declare BUMPS = 0; #end
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 0, -6>
  look_at <0, 0, 0>
  right x*image_width/image_height
  angle 40
}
background { rgb <0.2, 0.3, 0.6> }
light_source { <-10, 4, -3> color rgb 1 }

#declare NU = 12;
#declare NV = 8;
// P(I, J): the unit sphere's point at longitude step I, latitude step J
// (J = 0 the north pole); it is also the normal there.
#macro P(I, J)
  <cos(2*pi*I/NU)*sin(pi*J/NV), cos(pi*J/NV), sin(2*pi*I/NU)*sin(pi*J/NV)>
#end
mesh {
  #for (I, 0, NU - 1)
    #for (J, 0, NV - 1)
      #local A = P(I, J);
      #local B = P(I + 1, J);
      #local C = P(I + 1, J + 1);
      #local D = P(I, J + 1);
      #if (J > 0) smooth_triangle { A, A, B, B, C, C } #end
      #if (J < NV - 1) smooth_triangle { A, A, C, C, D, D } #end
    #end
  #end
  pigment { rgb <0.9, 0.7, 0.4> }
  finish { ambient 0.1 diffuse 0.9 }
  #if (BUMPS) normal { bumps 0.5 scale 0.15 } #end
  #if (NOSHADOW) no_shadow #end
  rotate <20, 30, 0>
  scale 1.5
}
