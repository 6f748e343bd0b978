// expect: 2:1: #break outside a #switch, #while or #for
#break
