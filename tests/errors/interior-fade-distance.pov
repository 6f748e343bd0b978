// expect: 2:40: fade_distance must be at least 0
sphere { 0, 1 interior { fade_distance -1 } }
