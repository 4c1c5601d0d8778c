(the manual's header: the modal state the example assumes)
G91;
N1 G28 Z0;
N2 G28 X0 Y0;
