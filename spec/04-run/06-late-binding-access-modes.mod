MODULE late_binding_access_modes
! @format 3
! @section 4.6
! @section 5.2
! @section 12
! @expect ok
! @description The access-mode table of section 5.2 holds for late-bound calls too, checked when the call runs: a constant, a literal or a FOR loop variable for a VAR or INOUT parameter raises ERR_ARGNOTVAR, a variable for a PERS parameter ERR_ARGNOTPER (chapter 12); the constant keeps its value. A variable for VAR and a persistent for PERS are aliases.
! @output constant to var: 
! @output argnotvar
! @output literal to var: 
! @output argnotvar
! @output loop variable to inout: 
! @output argnotvar
! @output variable to pers: 
! @output argnotper
! @output c=5
! @output v=7
! @output counter=8
! @exit 0
  CONST num c := 5;
  VAR num v;
  PERS num counter := 0;
  PROC set_var(VAR num x)
    x := 7;
  ENDPROC
  PROC set_inout(INOUT num x)
    x := 7;
  ENDPROC
  PROC set_pers(PERS num x)
    x := 8;
  ENDPROC
  PROC main()
    TPWrite "constant to var: ";
    % "set_var" % c;
    TPWrite "literal to var: ";
    % "set_var" % 3;
    FOR i FROM 1 TO 1 DO
      TPWrite "loop variable to inout: ";
      % "set_inout" % i;
    ENDFOR
    TPWrite "variable to pers: ";
    % "set_pers" % v;
    TPWrite "c=" \Num:=c;
    % "set_var" % v;
    TPWrite "v=" \Num:=v;
    % "set_pers" % counter;
    TPWrite "counter=" \Num:=counter;
  ERROR
    IF ERRNO = ERR_ARGNOTVAR THEN
      TPWrite "argnotvar";
      TRYNEXT;
    ELSEIF ERRNO = ERR_ARGNOTPER THEN
      TPWrite "argnotper";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
