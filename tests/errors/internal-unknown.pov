// expect: 2:25: there is no internal function 9999
#declare F = function { internal(9999) }
