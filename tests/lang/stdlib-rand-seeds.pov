// rand.inc: the rejection methods and the Rand_Gauss pair over 40 seeds,
// with the number drawn after each call. VRand_In_Obj prints with 5
// decimals: POV-Ray keeps bounding boxes in single precision.
#version 3.7;
#include "rand.inc"
#macro Show(N, V, S) #debug concat(N, " ", str(V, 0, 8), " ", str(rand(S), 0, 8), "\n") #end
#declare Ob = torus { 1, 0.1 rotate x*30 }
#for (K, 1, 40)
#declare S = seed(K * 7919);
Show(concat("N", str(K,0,0)), Rand_Normal(0, 1, S), S)
Show("G2.5", Rand_Gamma(2.5, 1, S), S)
Show("G1.1", Rand_Gamma(1.1, 1, S), S)
Show("G0.5", Rand_Gamma(0.5, 1, S), S)
Show("G0.7", Rand_Gamma(0.7, 2, S), S)
Show("B", Rand_Beta(0.7, 3, S), S)
Show("Ga", Rand_Gauss(1, 3, S), S)
Show("Po", Rand_Poisson(2.5, S), S)
Show("Ge", Rand_Geo(0.2, S), S)
Show("Bi", Rand_Binomial(5, 0.5, S), S)
Show("Be", Rand_Bernoulli(0.5, S), S)
Show("Er", Rand_Erlang(1.5, 2, S), S)
Show("Ca", Rand_Cauchy(0, 1, S), S)
#declare P = VRand_In_Obj(Ob, S);
#debug concat("Obj ", vstr(3, P, ",", 0, 5), "\n")
#end
