// expect: 2:29: undefined identifier 'Missing'
#declare F = function { x + Missing }
