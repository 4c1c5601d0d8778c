The program-start example of the manual (seed 003, section 2.3.1), number 200.
Expect: program number 200, no comment; the program has no blocks, which a full
compile reports (the main part ends with M02 or M30).
%200
