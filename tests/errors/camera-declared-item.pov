// expect: 3:12: expected a transformation or '}' (a declared camera may only be moved), found 'look_at'
#declare C = camera { location <0, 1, -5> }
camera { C look_at <0, 0, 0> }
