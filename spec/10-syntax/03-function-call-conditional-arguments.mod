MODULE function_call_conditional_argume
! @section 3.11
! @expect ok
! @description The conditional arguments of section 3.11, completed into routines that declare the optional parameters they pass on, and check itself.
  VAR num distance;
  VAR bool flag;
  PROC measure(pos p \pos b)
    distance := dist(\base ? b, p);
    IF Present(b) THEN
      distance := dist(\base:=b, p);
    ELSE
      distance := dist(p);
    ENDIF
  ENDPROC
  PROC choose(\num high | num low)
    flag := check(\on ? high \off ? low);
  ENDPROC
  FUNC bool check (\switch on | switch off)
    RETURN Present(on);
  ENDFUNC
ENDMODULE
