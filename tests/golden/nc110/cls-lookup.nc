; cls-lookup: (CLS,NAME[/DEV]) runs <library>/<DEV>/<NAME> or <NAME>.nc; the
; library is --lib, else the profile's nc110.program_library; without /DEV the
; device is nc110.default_device, MP0 by default (§2.13.2.2 L8419-8440;
; decision 21; docs/profile.md [nc110]).
; The trace names each called file; the called program returns at its end.
; P800 on MP2 (the manual's example)
N1 (CLS,P800/MP2)
; no device: MP0 by default (MP3 with profiles/flow-mp3.toml)
N2 (CLS,FLOWA)
; an explicit device
N3 (CLS,FLOWA/MP3)
; a file without the .nc extension
N4 (CLS,FLOWN/MP0)
N5 G X0
N6 M30
