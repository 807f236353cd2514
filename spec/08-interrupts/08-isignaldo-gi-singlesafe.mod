MODULE isignaldo_gi_singlesafe
! @format 3
! @section 8
! @expect ok
! @io io/edges.io
! @statement-time 0
! @description ISignalDO interrupts at the program's own changes of an output (here to 1); ISignalGI at every change of a group input (3 at 2.5 s, 9 at 3.5 s); \SingleSafe orders a single interrupt like \Single (doc/rulings.md R-8-h).
! @output do1 rose 2 times
! @output single safe 1
! @output gi1 changed 2 times
  VAR intnum rose;
  VAR intnum safe;
  VAR num n := 0;
  VAR num m := 0;
  VAR intnum group;
  VAR num g := 0;
  TRAP on_rise
    n := n + 1;
  ENDTRAP
  TRAP on_group
    g := g + 1;
  ENDTRAP
  TRAP on_safe
    m := m + 1;
  ENDTRAP
  PROC main()
    CONNECT rose WITH on_rise;
    ISignalDO do1, 1, rose;
    CONNECT safe WITH on_safe;
    ISignalDI \SingleSafe, di1, 1, safe;
    CONNECT group WITH on_group;
    ISignalGI gi1, group;
    Set do1;
    Reset do1;
    Set do1;
    WaitTime 5;
    TPWrite "do1 rose " + NumToStr(n, 0) + " times";
    TPWrite "single safe " \Num:=m;
    TPWrite "gi1 changed " + NumToStr(g, 0) + " times";
  ENDPROC
ENDMODULE
