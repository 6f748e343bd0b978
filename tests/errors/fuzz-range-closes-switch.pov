// expect: 7:5: the operands of #range closed the #switch they belong to (a directive among them)
// Fuzz run 21 (UBSan): the #end among #range's operands closed the #switch,
// the macro's end its frame, and the #switch's clause search then closed a
// block of the caller that was never opened (the block stack went below 0).
#macro Grade(N)
  #switch (N)
    #range (0, #end
#end
Grade(7) 5)
#end
#for (I, 1, 1) #end
