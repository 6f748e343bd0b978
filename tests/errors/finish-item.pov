// expect: 2:24: expected a finish item or '}', found 'sphere'
sphere { 0, 1 finish { sphere } }
