// expect: 3:1: #include may not read "../lib.sh": scene files can only read their own folder, the +L library paths and the stdlib (lucent --io-unrestricted lifts this)
// The file rule: a path with ".." that leaves the scene's folder is refused, though the file exists.
#include "../lib.sh"
