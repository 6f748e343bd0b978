// expect: 3:14: rand() needs a stream made by seed(), not -0.5
// found by fuzz_parse (CI of 1fe05ea): with no seed() yet, a stream in (-1, 0) read the missing table
#declare R = rand(-0.5);
