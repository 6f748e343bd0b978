// checks srgbf, srgbt and srgbft: filter/transmit stay linear (manual's equivalent forms)
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Foo = color srgbt <51,76,102,127>/255;
#debug concat("<",vstr(5,Foo,",",0,3),">\n")
#declare Foo = color srgbt <0.2, 0.3, 0.4, 0.5>;
#debug concat("<",vstr(5,Foo,",",0,3),">\n")
#declare Foo = color srgb <0.2, 0.3, 0.4> transmit 0.5;
#debug concat("<",vstr(5,Foo,",",0,3),">\n")
#declare Foo = color rgbt <0.033,0.073,0.133,0.5>;
#debug concat("<",vstr(5,Foo,",",0,3),">\n")
#declare G = srgbf <0.5, 0.5, 0.5, 0.5>;
#debug concat(vstr(5, G, ",", 0, 6), "\n")
#declare H = srgbft <0.5, 0.6, 0.7, 0.25, 0.75>;
#debug concat(vstr(5, H, ",", 0, 6), "\n")
