// expect: 3:18: undefined identifier 'Radius'
#declare Center = <0, 1, 0>;
sphere { Center, Radius }
