// expect: 2:8: expected '(' after #ifdef, found identifier 'A'
#ifdef A #end
