// expect: 2:30: ior must be greater than 0
sphere { 0, 1 interior { ior 0 } }
