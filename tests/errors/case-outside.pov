// expect: 2:1: #case outside a #switch
#case (1)
