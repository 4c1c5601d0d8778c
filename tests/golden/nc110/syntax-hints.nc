; syntax-hints: what a program copied from a document or written from another control
; gets told (decision 78): a typographic dash where a minus is meant (NC1001 with the
; hint; the quotes' hint is gtl-example-2-as-printed's), and R where G73 takes the
; lower-case r, the hole's radius (NC3033 with the hint).
G1 X–10 F100
G73 X10 Y10 R5 E40
