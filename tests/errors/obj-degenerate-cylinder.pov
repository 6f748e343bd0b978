// expect: 3:5: a cylinder's cap is at its base (a degenerate cylinder)
cylinder { <1, 2, 3>,
    <1, 2, 3>, 0.5 }
