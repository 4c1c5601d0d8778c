; The tool table's keys for tool life and wear (docs/profile.md, decisions 80-81), each
; refused at its place in profiles/tooling-bad.toml: a tool is not its own sister; a
; sister's corrector is one of [offsets], 1..9999; a maximum wear is not negative.
M30
