// expect: 4:13: macro calls nested too deeply (more than 1000 levels): is R recursing without end? (lucent --limit macro-depth=N raises the limit)
// expect-also: in macro R called from macro-recursion.pov:4:13 (and 998 more times from there)
// expect-also: in macro R called from macro-recursion.pov:5:14
#macro R(N) R(N + 1) #end
#declare X = R(0);
