// checks .red .green .blue .filter .transmit and .gray on colours
#version 3.7;
#declare Shade = rgbft <0.2, 0.4, 0.6, 0.8, 0.9>;
#debug concat("red=", str(Shade.red, 0, 6), "\n")
#debug concat("green=", str(Shade.green, 0, 6), "\n")
#debug concat("blue=", str(Shade.blue, 0, 6), "\n")
#debug concat("filter=", str(Shade.filter, 0, 6), "\n")
#debug concat("transmit=", str(Shade.transmit, 0, 6), "\n")
#debug concat("gray=", str(Shade.gray, 0, 6), "\n")
#debug concat("x=", str(Shade.x, 0, 6), " y=", str(Shade.y, 0, 6), " z=", str(Shade.z, 0, 6), " t=", str(Shade.t, 0, 6), "\n")
