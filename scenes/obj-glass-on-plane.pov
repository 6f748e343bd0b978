// obj-glass-on-plane.pov: a glass box standing on a checkered plane, seen
// from above through its top face. The box's bottom face and the plane
// coincide, so every ray refracted into the box meets both at the same t.
// lucent used to pick either by rounding (box.c's slab test and plane.c
// rounded t differently) and, when the box won, the ray left through the
// bottom below the plane and showed the background: blue speckles over
// 88% of the picture. Now both compute t alike and the unbounded plane
// wins the tie, as in POV-Ray. The box is wider than the view: rays that
// meet its side faces from inside refract differently in lucent (see
// tests/render/core.list).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

camera { location <0.2, 6, -1.5> right x*image_width/image_height look_at <0.2, 0, 0> angle 40 }
light_source { <4, 8, -6> color rgb 1 }
background { color rgb <0.2, 0.3, 0.5> }

plane { y, 0 pigment { checker color rgb 1 color rgb <0.1, 0.1, 0.1> scale 0.5 } }
box { <-4, 0, -4>, <4, 1, 4>
	pigment { color rgbf <0.9, 0.95, 1, 0.9> }
	finish { specular 0.5 roughness 0.02 }
	interior { ior 1.5 }
}
