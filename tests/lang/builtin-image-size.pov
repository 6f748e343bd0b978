// checks image_width and image_height (the runner renders at +W8 +H8)
#version 3.7;
#debug concat("image_width=", str(image_width, 0, 6), "\n")
#debug concat("image_height=", str(image_height, 0, 6), "\n")
#debug concat("ratio=", str(image_width/image_height, 0, 6), "\n")
#if (image_width < 300) #debug "small\n" #else #debug "large\n" #end
