; FLOWA on device MP3 (cls-lookup): another program of the same name.
(DIS,"FLOWA ON MP3")
G X30
