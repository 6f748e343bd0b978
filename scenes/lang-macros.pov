// lang-macros.pov: a scene built by the language rather than written out.
// Exercises #include of a file in the scene's folder (lang-macros.inc:
// an array of textures and a recursive macro), a macro calling itself
// (a branching tree, 6 levels, 127 branches), #for and #while loops with
// #local and #declare, #if/#else, #switch with #case and #range, arrays
// (a one-dimensional array filled in a loop, a two-dimensional one given
// whole, an element of a texture array as texture { Leaf[i] }), a
// spline evaluated along a path of spheres, string functions (concat,
// str, strlen) used in a condition, and vector functions (vnormalize,
// vcross, vrotate, vlength).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "lang-macros.inc"

camera { location <0, 4, -11> look_at <0, 2.2, 0> right x*image_width/image_height angle 50 }
light_source { <-6, 12, -9> color rgb 1 }
light_source { <8, 5, -4> color rgb 0.3 shadowless }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.55 } finish { ambient 0.25 } }

Tree(<0, 0, 0>, y, 1.8, 6)

// a ring of posts whose colour is chosen by #switch on the index
#declare N = 12;
#declare Heights = array[N];
#for (I, 0, N - 1)
  #declare Heights[I] = 0.4 + 0.3*mod(I, 3);
#end
#declare I = 0;
#while (I < N)
  #local P = vrotate(<4.2, 0, 0>, y*I*360/N);
  #switch (I)
    #case (0)
      #local Col = rgb <1, 1, 1>;
    #break
    #range (1, 5)
      #local Col = rgb <0.2, 0.4, 0.9>;
    #break
    #else
      #local Col = rgb <0.9, 0.4, 0.2>;
  #end
  cylinder { P, P + y*Heights[I], 0.2 pigment { Col } finish { specular 0.4 } }
  #declare I = I + 1;
#end

// a spline path of small spheres, every other one larger
#declare Path = spline {
  cubic_spline
  -0.25, <-5, 0.3, 2>
  0, <-4, 0.3, 3>
  0.5, <0, 1.5, 3.5>
  1, <4, 0.3, 3>
  1.25, <5, 0.3, 2>
}
#declare Grid = array[2][3] { {0.10, 0.14, 0.18}, {0.12, 0.16, 0.20} }
#for (K, 0, 20)
  #local T = K/20;
  sphere { Path(T), Grid[mod(K, 2)][mod(K, 3)] pigment { rgb <0.9, 0.8, 0.2> } }
#end

// a condition on strings: the box is there only if the label is 9 long
#declare Label = concat("lucent-", str(N, 0, 0));
#if (strlen(Label) = 9 & vlength(<3, 4, 0>) = 5)
  box { <-0.5, 0, -0.5>, <0.5, 0.6, 0.5> rotate y*30 translate <2.8, 0, -1.5>
        pigment { rgb <0.6, 0.2, 0.7> } finish { phong 0.6 } }
#end
