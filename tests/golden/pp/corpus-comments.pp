The comment examples of the manual (seed 003, section 2.2.1 c), verbatim, in a
program. Expect: N10 X100 Y100; N20 X200 Y200, its comment closed by the end of the
line, then a comment of one space and an empty open comment, all N20's; N30 X100
Y200 Z300 around a comment; N40 X100 only: its comment has no second quote, so the
end of the line ends it and Y200 Z300 are comment text. N35 (not the manual's) puts
Y and Z back to 0, so N40's move shows that it has no Y and no Z.
%3
N10 X100 Y100 " ЭТО КОММЕНТАРИЙ "
N20 X200 Y200 " ЭТО КОММЕНТАРИЙ
" "
"
N30 X100 "ЭТО КОММЕНТАРИЙ" Y200 Z300
N35 X0 Y0 Z0
N40 X100 "ЭТО КОММЕНТАРИЙ Y200 Z300
N50 M30
