The program-start example of the manual (seed 003, section 2.3.1), number 1.
Expect: program number 1, no comment; the program has no blocks, which a full
compile reports (the main part ends with M02 or M30).
%1
