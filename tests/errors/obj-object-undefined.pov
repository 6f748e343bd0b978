// expect: 2:10: undefined identifier 'Thing'
object { Thing }
