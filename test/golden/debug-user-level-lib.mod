MODULE debug_user_level_lib (NOSTEPIN)
  PROC Scale(num x)
    VAR num y;
    y := x / divisor;
    TPWrite "scaled " \Num:=y;
  ERROR
    RaiseToUser \Continue;
  ENDPROC
  PROC Fragile()
    RAISE 8;
  ERROR
    RaiseToUser \BreakOff \ErrorNumber:=9;
  UNDO
    TPWrite "Fragile undo";
  ENDPROC
ENDMODULE
