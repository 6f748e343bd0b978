// lang-default.pov: #default as POV-Ray reads it. A #default texture
// starts from the defaults in effect (here ambient 1 and diffuse 0: the
// red sphere is flat red), and a #default met while a #default part is
// read changes the defaults that part starts from (fuzz run 19: lucent
// leaked the default texture there, and then freed it under the reader).
// No light: every colour is pigment times ambient.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> look_at 0 right 8*x up 6*y }
#default { finish { ambient 1 diffuse 0 } }
#default { texture { pigment { rgb <1, 0, 0> } } }
sphere { <-2.5, 1.4, 0>, 1 }
#default { texture { #default { pigment { rgb <0, 1, 0> } } } }
sphere { <0, 1.4, 0>, 1 }
#default { pigment { #default { texture { pigment { rgb 1 } finish { ambient 0.5 diffuse 0 } } } rgb <0, 0, 1> } }
sphere { <2.5, 1.4, 0>, 1 }
#default { texture { pigment { #default { texture { pigment { rgb <1, 1, 0> } } } } } }
sphere { <-2.5, -1.4, 0>, 1 }
#default { texture { pigment { rgb 1 } finish { ambient 1 diffuse 0 } } }
#default { finish { #default { finish { ambient 0.3 } } diffuse 0 } }
sphere { <0, -1.4, 0>, 1 }
#default { normal { #default { texture { pigment { rgb <0, 1, 1> } } } bumps 0.5 } }
sphere { <2.5, -1.4, 0>, 1 }
