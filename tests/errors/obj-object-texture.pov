// expect: 3:10: 'T' is a texture, not an object
#declare T = texture { pigment { rgb 1 } }
object { T }
