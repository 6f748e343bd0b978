// Accuracy sweep (tests/bench/accuracy.sh): soft shadows from one square
// area light over a sphere, a box and a thin post on a white floor. The
// sweep sets the light's grid through declares (defaults in brackets):
//   AL_N   samples along each side of the grid [5]
//   AL_AD  adaptive level, -1 for none [1]
//   AL_J   1 jitters the samples [1]
#version 3.7;
#ifndef (AL_N) #declare AL_N = 5; #end
#ifndef (AL_AD) #declare AL_AD = 1; #end
#ifndef (AL_J) #declare AL_J = 1; #end
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 }
sphere { <-1.2,0.8,0>, 0.8 pigment { rgb <1,0.9,0.7> } finish { Mat } }
box { <0.5,0.01,-0.4>, <1.5,1.6,0.4> rotate y*25 pigment { rgb <0.7,0.8,1> } finish { Mat } }
cylinder { <0,0.01,1.5>, <0,2.2,1.5>, 0.15 pigment { rgb 1 } finish { Mat } }
light_source {
  <-1,5,-1>, rgb 1
  area_light <4,0,0>, <0,0,4>, AL_N, AL_N
  #if (AL_AD >= 0) adaptive AL_AD #end
  #if (AL_J) jitter #end
}
