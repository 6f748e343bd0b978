// expect: 2:10: expected an object identifier or an object, found number 5
object { 5 }
