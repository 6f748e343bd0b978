// expect: 6:3: the operands of #case closed the #switch they belong to (a directive among them)
// A #case reached by falling through still reads its operands, which must
// leave the #switch open too.
#switch (1)
  #case (1) #declare A = 1;
  #case (#end 2)
#end
