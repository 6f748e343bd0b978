// expect: 2:99: a function has at most 32 parameters
#declare F = function(a,b,c,d,e,f,g,h,i,j,k,l,m,n,o,p,q,r,s,tt,uu,vv,w,xx,yy,zz,a1,b1,c1,d1,e1,f1,g1) { a }
