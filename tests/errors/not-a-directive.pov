// expect: 2:2: expected a directive name after '#', found identifier 'frobnicate'
#frobnicate
