// expect: 2:14: a cone's cap is at its base (a degenerate cone)
cone { y, 1, <0,1,0>, 0.5 }
