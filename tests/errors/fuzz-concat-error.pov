// expect: 4:38: undefined identifier 'Lv'
// Found by fuzzing: an error inside concat()'s arguments leaked the string being built
// (LeakSanitizer in make check-sanitize).
#debug concat("inner include: ", str(Lv, 0, 0), "\n")
