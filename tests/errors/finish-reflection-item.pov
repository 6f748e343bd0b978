// expect: 2:42: expected a reflection item (fresnel, falloff, exponent, metallic) or '}', found 'phong'
sphere { 0, 1 finish { reflection { 0, 1 phong 1 } } }
