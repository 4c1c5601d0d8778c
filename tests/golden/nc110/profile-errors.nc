; The [nc110] settings of a machine profile (docs/profile.md): each wrong value is
; NC6004 at the value in profiles/check-bad-nc110.toml, all of them at once, and the
; program is not checked (exit 2, as for every error of the command line or its files).
G0 X10
M30
