// checks ?:, comparisons, logic and built-ins in expressions run many times
#version 3.7;
#declare I = 0;
#while (I <= 6 & I != 7)
  #declare A = (I > 2 ? I * I : -I);
  #declare B = max(I, 3, A) + min(I, 2) + abs(-I) + mod(I, 4) + int(I / 4);
  #declare C = (I >= 3) + (I <= 3) * 10 + (I = 3) * 100 + !(I < 5) * 1000;
  #declare D = sqrt(I) + pow(2, I) + sin(I) + atan2(I, 2) + floor(-I / 3) + ceil(I / 3);
  #debug concat(str(A, 0, 0), " ", str(B, 0, 0), " ", str(C, 0, 0), " ", str(D, 0, 6), "\n")
  #declare I = I + 1;
#end
