# three lines of comments
#

opacity 0 0
opacitty 1 0.5
