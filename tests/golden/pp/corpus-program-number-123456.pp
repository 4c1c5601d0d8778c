The program-start example of the manual (seed 003, section 2.3.1): six digits, the
most a program number has, and a comment without its closing quote. The seed prints
the quote as U+201C, which is not the comment character '"': expect an error there,
and the report that the program has no blocks.
%123456  “КОММЕНТАРИЙ:
