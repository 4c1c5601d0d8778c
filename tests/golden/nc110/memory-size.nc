; memory-size: the sizes of SA, SK and SYVAR come from the profile's nc110.memories
; (Table 2.7, §2.10.4 L5038 SA 1024 bytes, §2.10.5 L5109 SYVAR 200 by default; decision
; 17). With the default profile every reference below is in range; with
; profiles/lang-memories.toml (SA 2, SK 4, SYVAR 16 bytes) lines 7, 10 and 12 are NC2014.
SYVAR15=1
SYVAR1.LR=1
SYVAR16=1
SK3=1
SK1.IN=1
SK2.IN=1
SA15=1
SA16=1
