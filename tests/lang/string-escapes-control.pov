// checks the control escapes \a \b \f \v and \uNNNN through asc() and strlen()
#version 3.7;
#debug concat(str(asc("\a"), 0, 0), " ", str(asc("\b"), 0, 0), " ", str(asc("\f"), 0, 0), " ", str(asc("\v"), 0, 0), " ", str(asc("\r"), 0, 0), "\n")
#debug concat(str(asc("\u0041"), 0, 0), " ", str(asc("\u00e9"), 0, 0), " ", str(strlen("\u00e9\u0041"), 0, 0), "\n")
#debug "[\u0041\u0042\u0043]\n"
#debug "x\ay\bz\fw\vq\n"
