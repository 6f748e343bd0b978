// expect: 3:1: #include may not read "/etc/passwd": scene files can only read their own folder, the +L library paths and the stdlib (lucent --io-unrestricted lifts this)
// The file rule: an absolute path outside the allowed folders is refused.
#include "/etc/passwd"
