// expect: 5:24: distribution 2 takes 1 ray per pixel, not 2147483647
// Found by fuzz_parse (CI's check-fuzz): a ray count of 3.3e113 was cast to
// int, undefined behaviour; it saturates now.
#declare V = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333333 2 0 mesh { V } } }
