The same program start with the ASCII quote: the comment ends at the end of the line
and is the program's title (decision 2). Expect only the report that the program has
no blocks.
%123456  "КОММЕНТАРИЙ:
