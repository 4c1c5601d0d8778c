; system-value-rms: RMS is a whole percentage 0..255 (§2.10.3 seed L5002-5025, class BY;
; decision 16): RMS=256 is NC4048 at line 4.
RMS=255
RMS=256
