// rand.inc: one call of each macro on a fresh stream, with the number
// drawn after it (which shows how many numbers the macro drew), and the
// predefined streams. Rand_Student, Rand_Chi_Square and Rand_F_Dist use 4
// degrees of freedom: POV-Ray 3.7's give the 4-degree distributions for
// any N (see doc/stdlib.md). Rand_Tri and Rand_Spline fail in POV-Ray 3.7.
#version 3.7;
#include "rand.inc"
#declare R = seed(42);
#debug "raw:"
#for (I, 0, 11) #debug concat(" ", str(rand(R), 0, 10)) #end
#debug "\n"
#declare S = seed(42); #declare V = SRand(S); #debug concat("SRand ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = RRand(2, 5, S); #debug concat("RRand ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = VRand(S); #debug concat("VRand ", vstr(3,V,",",0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = VRand_In_Box(<1,2,3>, <2,4,7>, S); #debug concat("VRand_In_Box ", vstr(3,V,",",0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = VRand_In_Sphere(S); #debug concat("VRand_In_Sphere ", vstr(3,V,",",0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = VRand_On_Sphere(S); #debug concat("VRand_On_Sphere ", vstr(3,V,",",0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Cauchy(1, 2, S); #debug concat("Rand_Cauchy ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Student(4, S); #debug concat("Rand_Student ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Normal(1, 2, S); #debug concat("Rand_Normal ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Gauss(1, 2, S); #debug concat("Rand_Gauss ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Gamma(2.5, 1.5, S); #debug concat("Rand_Gamma ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Gamma(0.5, 1.5, S); #debug concat("Rand_Gamma small ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Beta(2, 3, S); #debug concat("Rand_Beta ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Chi_Square(4, S); #debug concat("Rand_Chi_Square ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_F_Dist(4, 4, S); #debug concat("Rand_F_Dist ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Erlang(2, 3, S); #debug concat("Rand_Erlang ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Exp(2, S); #debug concat("Rand_Exp ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Lognormal(1, 2, S); #debug concat("Rand_Lognormal ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Pareto(2, S); #debug concat("Rand_Pareto ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Weibull(2, 3, S); #debug concat("Rand_Weibull ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Bernoulli(0.3, S); #debug concat("Rand_Bernoulli ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Prob(0.3, S); #debug concat("Prob ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Binomial(10, 0.3, S); #debug concat("Rand_Binomial ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Geo(0.3, S); #debug concat("Rand_Geo ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Poisson(3, S); #debug concat("Rand_Poisson ", str(V,0,10), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare Ob = sphere { <1,2,3>, 0.5 } #declare V = VRand_In_Obj(Ob, S); #debug concat("VRand_In_Obj ", vstr(3,V,",",0,5), " next ", str(rand(S),0,10), "\n")
#declare S = seed(42); #declare V = rand(RdmA); #debug concat("RdmA ", str(V,0,10), " ", str(rand(RdmB),0,10), " ", str(rand(RdmC),0,10), " ", str(rand(RdmD),0,10), "\n")
#declare S = seed(42); #declare V = Rand_Gauss(1, 2, S); #declare V2 = Rand_Gauss(1, 2, S); #declare V3 = Rand_Gauss(1, 2, S); #debug concat("Rand_Gauss x3 ", str(V,0,10), " ", str(V2,0,10), " ", str(V3,0,10), " next ", str(rand(S),0,10), "\n")
