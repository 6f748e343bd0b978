// arrays.inc: sorting (whole and partial, with repeated values, and with
// Sort_Compare and Sort_Swap_Data redeclared for the rows of a 2D array),
// reversing, resizing and picking items. ARRAYS_WriteDF3 writes files
// POV-Ray's writes byte for byte (checked by hand: lucent cannot read df3).
#version 3.7;
#include "arrays.inc"
#macro PA(N, A) #debug concat(N, ":") #for (I, 0, dimension_size(A,1)-1) #ifdef (A[I]) #debug concat(" ", str(A[I],0,3)) #else #debug " -" #end #end #debug "\n" #end
#declare A = array[7] {5, 3, 9, 1, 7, 3, 2}
PA("A", A)
Sort_Array(A)
PA("sorted", A)
#declare B = array[8] {8, 7, 6, 5, 4, 3, 2, 1}
Sort_Partial_Array(B, 2, 5)
PA("partial", B)
Reverse_Array(B)
PA("reversed", B)
#declare C = array[3] {1, 2, 3}
Resize_Array(C, 5)
PA("grown", C)
Resize_Array(C, 2)
PA("shrunk", C)
#declare R = seed(3);
#declare D = array[5] {10, 20, 30, 40, 50}
#for (I, 0, 9) #debug concat(" ", str(Rand_Array_Item(D, R), 0, 0)) #end
#debug "\n"
#declare E = array[6] {4, -1, 4, 0, -1, 2.5}
Sort_Array(E)
PA("E", E)
#declare Big = array[10]
#declare R2 = seed(17);
#for (I, 0, 9) #declare Big[I] = floor(rand(R2) * 50); #end
Sort_Array(Big)
PA("big", Big)
#declare Table = array[5][2] {{3, 30}, {1, 10}, {5, 50}, {2, 20}, {4, 40}}
#macro Sort_Compare(Array, IdxA, IdxB)
	(Array[IdxA][1] > Array[IdxB][1])
#end
#macro Sort_Swap_Data(Array, IdxA, IdxB)
	#local T0 = Array[IdxA][0];
	#local T1 = Array[IdxA][1];
	#declare Array[IdxA][0] = Array[IdxB][0];
	#declare Array[IdxA][1] = Array[IdxB][1];
	#declare Array[IdxB][0] = T0;
	#declare Array[IdxB][1] = T1;
#end
Sort_Array(Table)
#for (I, 0, 4) #debug concat("row ", str(Table[I][0], 0, 0), " ", str(Table[I][1], 0, 0), "\n") #end
