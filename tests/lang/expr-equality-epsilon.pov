// checks that = and != compare with a tolerance of about 1e-10
#version 3.7;
#debug concat("(1=1+1e-12)=", str((1=1+1e-12), 0, 6), "\n")
#debug concat("(1!=1+1e-12)=", str((1!=1+1e-12), 0, 6), "\n")
#debug concat("(1=1+1e-6)=", str((1=1+1e-6), 0, 6), "\n")
#debug concat("(0=1e-11)=", str((0=1e-11), 0, 6), "\n")
#debug concat("(0.1+0.2=0.3)=", str((0.1+0.2=0.3), 0, 6), "\n")
#debug concat("(0.1+0.2!=0.3)=", str((0.1+0.2!=0.3), 0, 6), "\n")
