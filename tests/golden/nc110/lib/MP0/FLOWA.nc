; FLOWA on device MP0 (cls-lookup): a message and a rapid move to X10.
(DIS,"FLOWA ON MP0")
G X10
