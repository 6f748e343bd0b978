// expect: 2:1: #break outside a #switch, #while, #for or macro
#break
