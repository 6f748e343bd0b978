// checks a colour identifier followed by component keywords (replaces those components)
#version 3.7;
#declare My_Color = rgbft <0.2, 0.4, 0.6, 0.1, 0.3>;
#declare A = color My_Color red 0.5;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#declare B = color My_Color filter 0.9 blue 0;
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#declare Cyan = color blue 1.0 green 1.0;
#declare LightCyan = color Cyan red 0.6;
#debug concat(vstr(5, LightCyan, ",", 0, 6), "\n")
#declare D = color My_Color green 0 transmit 0 red 1;
#debug concat(vstr(5, D, ",", 0, 6), "\n")
