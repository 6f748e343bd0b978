// expect: 3:18: undefined identifier 'Missing'
// expect-also: in macro Bad called from error-in-macro.pov:4:14
#macro Bad() 1 + Missing #end
#declare X = Bad();
