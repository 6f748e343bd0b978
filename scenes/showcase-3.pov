// showcase-3.pov: a colonnade at dusk. A ring of columns (cylinders with
// torus collars, built by a #for loop and rotated into place) carrying
// arches cut from a ring (difference of cylinders and boxes), on a floor
// of hexagon tiles, round a basin with a mirror-still water disc and a
// superellipsoid plinth holding a prism star. Lit by a low, warm
// parallel sun, a cylinder light falling on the plinth and two coloured
// spotlights, with ground fog pooling on the floor and a rainbow in the
// sky_sphere. Exercises #for/#local/#if, vrotate, union and difference, object
// identifiers reused with transforms, cylinder, torus, superellipsoid,
// prism (linear spline), disc, the hexagon and gradient patterns, mirror
// reflection, parallel, cylinder and spot lights, fog_type 2, rainbow and
// sky_sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 4.2, -9.5>
  look_at <0, 1.2, 0.5>
  right x*image_width/image_height
  angle 55
}
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.9, 0.45, 0.2>] [0.25 rgb <0.35, 0.25, 0.5>] [1 rgb <0.05, 0.05, 0.2>] } }
}
rainbow {
  angle 42.5 width 5 distance 1e3 direction <-0.2, -0.3, 1> jitter 0
  color_map {
    [0 rgbt <1, 0, 0, 1>] [0.1 rgbt <1, 0, 0, 0.7>] [0.3 rgbt <1, 1, 0, 0.7>]
    [0.5 rgbt <0, 1, 0, 0.7>] [0.7 rgbt <0, 0, 1, 0.7>] [0.9 rgbt <0.5, 0, 1, 0.7>] [1 rgbt <0.5, 0, 1, 1>]
  }
}
fog { fog_type 2 distance 6 color rgbf <0.6, 0.55, 0.7, 0.3> fog_offset 0.1 fog_alt 0.4 }

light_source { <-30, 12, -20> color rgb <1, 0.8, 0.6> parallel point_at <0, 0, 0> }
light_source {
  <0, 8, 0> color rgb <0.9, 0.9, 1>
  cylinder point_at <0, 0, 0> radius 0.8 falloff 1.4 tightness 3
}
light_source { <-5, 6, -6> color rgb <0.3, 0.5, 1> spotlight point_at <-2, 0, 2> radius 15 falloff 25 }
light_source { <5, 6, -6> color rgb <1, 0.4, 0.5> spotlight point_at <2, 0, 2> radius 15 falloff 25 }

// floor
plane {
  y, 0
  pigment { hexagon rgb <0.55, 0.5, 0.45>, rgb <0.35, 0.33, 0.3>, rgb <0.7, 0.62, 0.5> scale 0.5 }
  finish { ambient 0.15 diffuse 0.75 specular 0.2 }
}

// columns and arches on a ring of radius 4
#declare N = 10;
#declare R = 4;
#declare Stone = texture {
  pigment { gradient y color_map { [0 rgb <0.85, 0.8, 0.7>] [1 rgb <0.7, 0.65, 0.6>] } scale 3 }
  finish { ambient 0.15 diffuse 0.75 specular 0.15 }
}
#declare Column = union {
  cylinder { <0, 0, 0>, <0, 2.6, 0>, 0.22 }
  torus { 0.25, 0.05 translate y*0.15 }
  torus { 0.25, 0.05 translate y*2.45 }
  box { <-0.32, 2.6, -0.32>, <0.32, 2.75, 0.32> }
}
#for (I, 0, N - 1)
  #local A = 360*I/N + 18;
  #local P = vrotate(<R, 0, 0>, y*A);
  #if (P.z > -1.5)
    object { Column texture { Stone } translate P }
  #end
#end
// the arches: a ring of stone, with a round opening between each pair of
// columns, cut away near the camera
difference {
  cylinder { <0, 2.75, 0>, <0, 3.6, 0>, R + 0.35 }
  cylinder { <0, 2.7, 0>, <0, 3.7, 0>, R - 0.35 }
  #for (I, 0, N - 1)
    #local A = 360*(I + 0.5)/N + 18;
    cylinder { <0, 2.75, -0.6>, <0, 2.75, 0.6>, 0.5 scale <1, 1.2, 1> rotate y*90 translate <R, 0, 0> rotate y*A }
  #end
  box { <-8, 2, -8>, <8, 4, -1.5> }
  texture { Stone }
}

// basin, water and plinth with a star
difference {
  cylinder { <0, 0, 0>, <0, 0.45, 0>, 1.8 }
  cylinder { <0, 0.1, 0>, <0, 0.6, 0>, 1.6 }
  texture { Stone }
}
disc { <0, 0.35, 0>, y, 1.6 pigment { rgb <0.05, 0.12, 0.15> } finish { ambient 0 diffuse 0.1 reflection 0.8 } }
superellipsoid {
  <0.25, 0.25>
  scale <0.35, 0.6, 0.35> translate y*0.6
  texture { Stone }
}
prism {
  linear_spline 0, 0.12, 11,
  <0, 1>, <0.22, 0.3>, <0.95, 0.31>, <0.36, -0.12>, <0.59, -0.81>,
  <0, -0.38>, <-0.59, -0.81>, <-0.36, -0.12>, <-0.95, 0.31>, <-0.22, 0.3>, <0, 1>
  rotate x*-90 scale 0.5 translate y*1.7
  pigment { rgb <1, 0.8, 0.2> }
  finish { ambient 0.3 diffuse 0.6 specular 0.8 metallic reflection 0.2 }
}
