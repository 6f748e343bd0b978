// functions.inc: bit-exact values and signs of zero. S prints a value to
// 10 decimals, which shows the sign of an exact zero (-0.0000000000); B
// prints it as a binary mantissa to 20 decimals and a power of 2, which
// pins down every bit. The zeros are the field-strength functions (and
// f_spikes_2d) at points where their terms cancel exactly or vanish, with
// zero and -0 coordinates and parameters and a SOR switch with a zero
// angle, where the order of the terms decides the sign; the B values are
// points where large terms nearly cancel (tests/unit/fn_internal_sweep.sh
// found them). Values recorded by POV-Ray 3.7.
#version 3.7;
#include "functions.inc"
#macro S(N, V) #debug concat(N, " ", str(V, 0, 10), "\n") #end
#declare E2 = function(v) { floor(ln(abs(v)) / ln(2)) }
#macro B(N, V) #debug concat(N, " ", str(V * pow(2, -E2(V)), 0, 20), " * 2^", str(E2(V), 0, 0), "\n") #end
S("umbrella", f_umbrella(0, 0, -1.1154, 2.9444))
S("umbrella", f_umbrella(0, 0, 1.9348, -1))
S("umbrella", f_umbrella(0, 2, -0.0, 2))
S("witch_of_agnesi", f_witch_of_agnesi(1.8923, 0, -1.6766, 0, 0))
S("witch_of_agnesi", f_witch_of_agnesi(1.9278, 0, -1.5499, -3, 0))
S("witch_of_agnesi_2d", f_witch_of_agnesi_2d(2.3243, 0, 3.3544, 2, 3.0, 0, -1.9082, 0, -1.0))
S("witch_of_agnesi_2d", f_witch_of_agnesi_2d(-1, -0.0, -0.0, 0, 0.611, 0, 0.5, -2, 0))
S("strophoid", f_strophoid(0, -2.5634, 3.5903, 0, -2.482, 0, 0))
S("strophoid", f_strophoid(0, 1.479, 0.1194, -3.0, 6.1832e-05, 0, 0))
S("strophoid", f_strophoid(0.5, -0.0, 0, 0.049, 2.675, 0, -0.0))
S("strophoid_2d", f_strophoid_2d(2.9659, 0, -3.0758, 5, -1, 0, 0, 0, 0, 0.5775))
S("strophoid_2d", f_strophoid_2d(2.42, 0, -0.0, -2, 0.5, 1, 0, -2, 0.5, -0.5))
S("quartic_cylinder", f_quartic_cylinder(-3.2912, 0, 0.5, 0.09231565, 0, 0))
S("quartic_cylinder", f_quartic_cylinder(0.0, -0.9913, 0, -2.5, 3.5408, 0))
S("torus2", f_torus2(-2.0, 0, 0, -1.6898, 1, -1))
S("mitre", f_mitre(0, 0, -0.5, 3.7372))
S("lemniscate_of_gerono", f_lemniscate_of_gerono(0.0, 0, 0, 5))
S("lemniscate_of_gerono_2d", f_lemniscate_of_gerono_2d(0.7918, 0, 2.2866, 0, -3.6409, 0, 0, -31.117, -35.41))
S("kampyle_of_eudoxus", f_kampyle_of_eudoxus(2, 0, 0, 3, 0, 0))
S("kampyle_of_eudoxus_2d", f_kampyle_of_eudoxus_2d(0, 0, -0.8014, 1.0, 0.1928, 3, -1, 5.5, 0))
S("kampyle_of_eudoxus_2d", f_kampyle_of_eudoxus_2d(-3.9697, 0, -0.6397, -36.077, 1, 0, 1, 4, 0))
S("piriform_2d", f_piriform_2d(1.0209, 0, 0.548, 1, 0, 0, 3.2268, 0, -1, -1))
S("piriform_2d", f_piriform_2d(-3.2555, 0, -1.4868, -47.071, 1.5, 2.5, 0, 0.6433, 3.0, 0))
S("spikes_2d", f_spikes_2d(-1.6443, 0, -3.6486, 0, -1.0, -0.5, 3.5))
S("spikes_2d", f_spikes_2d(2.073, 0, -1.1333, 0, 3.4649, 0, 3.9871))
S("nodal_cubic", f_nodal_cubic(-3.6856, 0, 0, -2.5))
S("nodal_cubic", f_nodal_cubic(-2.2683, 0, 0, 2.8137))
S("bifolia", f_bifolia(0, 0, 0, 1.2005, 4.5))
S("quartic_paraboloid", f_quartic_paraboloid(0, 0, 0, 4.5))
S("quartic_saddle", f_quartic_saddle(2, 0, -2, 2))
S("paraboloid", f_paraboloid(0, 0, 0, 1))
S("cubic_saddle", f_cubic_saddle(1, 1, 0, -2))
S("devils_curve", f_devils_curve(0, 0, 0, -2.472))
S("devils_curve_2d", f_devils_curve_2d(-0.5, 0, 3, 2, 0.5, -0.352, -2, 0, 0.5))
S("enneper", f_enneper(0.5, -0.5, 0, -2))
S("heart", f_heart(0, 1, 0, 0.5))
S("hyperbolic_torus", f_hyperbolic_torus(2, -0.5, -2, 0.5, 0, -0.5))
S("kummer_surface_v1", f_kummer_surface_v1(1, 1, 0, 0))
S("kummer_surface_v2", f_kummer_surface_v2(1, 0, 0, -1.644, 0, 0, 1))
S("ovals_of_cassini", f_ovals_of_cassini(0, 0, 0, 0, 1, -1, -1.263))
S("parabolic_torus", f_parabolic_torus(0, 0, 0, -1.154, 0.5, -0.5))
S("algbr_cyl2", f_algbr_cyl2(1, 2, -2, 0.5, 3, 0, 0, 3))
S("algbr_cyl3", f_algbr_cyl3(0, 0, 0.9662, -3, 1, 0, 146.1, 2.453))
S("algbr_cyl4", f_algbr_cyl4(0, 1, 0.5, -0.5, 1, 0, -1.492, -0.5))
B("hyperbolic_torus", f_hyperbolic_torus(-0.6646, -3.7201, 2.8982, -2.6293, 0, 2.503))
B("hyperbolic_torus", f_hyperbolic_torus(-1.3866, -3.8146, 0, 32.977, -6.199e-06, 4))
B("hyperbolic_torus", f_hyperbolic_torus(1.7694, 3.8586, 3.7933, -1, -1.395e-06, -2))
B("hyperbolic_torus", f_hyperbolic_torus(-2.5372, 0, 1.4157, 0.7091, 1.5209, -3.621))
B("torus2", f_torus2(-3.6692, 1.7536, -2.8833, 1.3912, 1.3392, -3.7619))
B("torus2", f_torus2(1.5621, 0.0946, -3.0891, -2.0, -3.5828, 0.313))
B("torus2", f_torus2(1.4623, 1.6288, -2.0425, -1.0, 0.000138061, 3))
