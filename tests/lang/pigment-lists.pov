// checks block-pattern colour and pigment lists with POV-Ray's defaults for missing entries, and color_map forms
#version 3.7;
#declare Ck1 = function { pigment { checker color rgb <1, 0, 0> } }
#declare Ck0 = function { pigment { checker } }
#declare Hx = function { pigment { hexagon color rgb 0.1, color rgb 0.2 } }
#declare Br = function { pigment { brick color rgb 1 color rgb <0.5, 0, 0> brick_size <1, 1, 1> mortar 0.2 } }
#declare Sq = function { pigment { square pigment { rgb 0.25 } pigment { checker color rgb 1 color rgb 0 scale 0.1 } } }
#declare Old = function { pigment { gradient x color_map { [0.2 0.6 color rgb 0 color rgb 1] } } }
#declare Mix = function { pigment { gradient x colour_map { [0, rgb <1, 0, 0>] [0.5 color rgb <0, 1, 0>] [1 color red 0 green 0 blue 1] } } }
#declare CM = color_map { [0 rgb 1] [1 rgb 0] }
#declare Id = function { pigment { gradient y color_map { CM } } }
#declare PM = function { pigment { gradient x pigment_map { [0 rgb 1] [1 checker color rgb <1,0,0> color rgb <0,0,1>] } } }
#debug concat(vstr(3, Ck1(0.5, 0.5, 0.5), ",", 0, 4), " ", vstr(3, Ck1(1.5, 0.5, 0.5), ",", 0, 4), " ", vstr(3, Ck0(0.5, 0.5, 0.5), ",", 0, 4), "\n")
#debug concat(vstr(3, Hx(0, 0, 0), ",", 0, 4), " ", vstr(3, Hx(0.8, 0, 0.5), ",", 0, 4), " ", vstr(3, Hx(1.5, 0, 0.9), ",", 0, 4), "\n")
#debug concat(vstr(3, Br(0.5, 0.5, 0.5), ",", 0, 4), " ", vstr(3, Br(0.05, 0.5, 0.5), ",", 0, 4), "\n")
#debug concat(vstr(3, Sq(0.5, 0, 0.5), ",", 0, 4), " ", vstr(3, Sq(0.55, 0, -0.55), ",", 0, 4), " ", vstr(3, Sq(-0.5, 0, -0.5), ",", 0, 4), "\n")
#debug concat(vstr(3, Old(0.1, 0, 0), ",", 0, 4), " ", vstr(3, Old(0.4, 0, 0), ",", 0, 4), " ", vstr(3, Old(0.8, 0, 0), ",", 0, 4), "\n")
#debug concat(vstr(3, Mix(0.25, 0, 0), ",", 0, 4), " ", vstr(3, Mix(0.75, 0, 0), ",", 0, 4), " ", vstr(3, Id(0, 0.3, 0), ",", 0, 4), "\n")
#debug concat(vstr(3, PM(0.5, 0.5, 0.5), ",", 0, 4), " ", vstr(3, PM(0.5, 1.5, 0.5), ",", 0, 4), "\n")
