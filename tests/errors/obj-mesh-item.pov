// expect: 4:3: expected an object modifier or '}', found 'sphere'
mesh {
  triangle { <0,0,0>, <1,0,0>, <0,1,0> }
  sphere { 0, 1 }
}
