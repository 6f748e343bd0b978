// atmos-alpha-filter.pov: with +UA, see-through objects over the
// transparent background give partial alpha as in POV-Ray 3.7: 1 minus the
// share of the background seen through them (each surface passes the grey
// of its filter * colour + transmit), and a highlight makes a clear
// surface as opaque as it is bright.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 8, -8> color rgb 1 }
#declare Clear = finish { ambient 0.2 diffuse 0.6 phong 0.8 phong_size 40 }
sphere { <-2.2, 1, 0>, 0.8 pigment { rgbf <1, 0.3, 0.2, 0.6> } finish { Clear } }
sphere { <-0.4, 1, 0>, 0.8 pigment { rgbt <0.2, 0.4, 1, 0.5> } finish { Clear } }
sphere { <1.4, 1, 0>, 0.8 pigment { rgbft <0.9, 1, 0.8, 0.7, 0.2> } finish { Clear reflection 0.1 }
  interior { ior 1.5 } }
sphere { <0.5, 2.3, 1>, 0.5 pigment { rgbt 1 } finish { ambient 0 diffuse 0 phong 1 phong_size 10 } }
box { <-1.5, -0.5, 1.5>, <2.5, 0.3, 2> pigment { rgb <0.9, 0.7, 0.3> } }
