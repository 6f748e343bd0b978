// expect: 3:27: the array would have more than 100000000 elements (lucent --limit array-size=N raises the limit)
// The array size limit: the error comes before any memory is taken.
#declare A = array[20000][20000];
