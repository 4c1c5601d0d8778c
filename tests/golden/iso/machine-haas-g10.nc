(--machine haas, decisions 59 and 61: G10 L2 loads G54, L20 P3 the extended work offset G154 P3, L10/L11 offset 7's length geometry and wear, G91 adds to the wear; G154 P3 selects it; the haas tables' M88/M89 are through-spindle coolant; inch units by Setting 9)
G90 G00 X0 Y0 Z0;
T7 M06;
G10 L2 P1 X-10. Y-5. Z-2.;
G54 X0 Y0;
G43 H7 Z1.;
G10 L10 P7 R4.5;
G10 L11 P7 R-0.01;
G91 G10 L11 P7 R-0.005;
G90 G10 L20 P3 X-1.;
G154 P3 X1.;
G111 X1.;
M88;
M89;
M30;
