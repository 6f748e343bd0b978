// expect: 3:58: expected a 2-component uv vector, found a string
mesh {
  triangle { <0,0,0>, <1,0,0>, <0,1,0> uv_vectors <0,0>, "b", <0,1> }
}
