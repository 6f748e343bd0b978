// expect: 2:35: expected thickness, turbulence or '}', found 'phong'
sphere { 0, 1 finish { irid { 0.3 phong 1 } } }
