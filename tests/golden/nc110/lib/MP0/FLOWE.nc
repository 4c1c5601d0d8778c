; FLOWE (epp-nested-runtime): runs a range of its own with (EPP,S,T).
"S" E5=E5+1
"T" E6=E6+1
(EPP,S,T)
