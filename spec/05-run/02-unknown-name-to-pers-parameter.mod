MODULE unknown_name_to_pers_parameter
! @format 3
! @section 5.2
! @section 4.6
! @section 13
! @options allow-unknown
! @expect ok
! @description Ruling R-5.2-unknown1: with --allow-unknown, a name neither declared nor installed passed to a PERS parameter is unknown (ERR_REFUNKDAT, ch. 12), not "not a persistent" (ERR_ARGNOTPER): in a direct call, a late-bound one and a call of an installed routine (IPers), as for a VAR parameter; a variable that is declared is still ERR_ARGNOTPER.
! @output direct ERR_REFUNKDAT=TRUE
! @output late ERR_REFUNKDAT=TRUE
! @output late VAR ERR_REFUNKDAT=TRUE
! @output installed ERR_REFUNKDAT=TRUE
! @output declared variable ERR_ARGNOTPER=TRUE
! @exit 0
  VAR num phase := 0;
  VAR num known := 1;
  VAR intnum watch;
  PROC need_pers(PERS num y)
    TPWrite "not entered";
  ENDPROC
  PROC need_var(VAR num y)
    TPWrite "not entered";
  ENDPROC
  PROC main()
    phase := 1;
    need_pers tool_undeclared;
    phase := 2;
    % "need_pers" % tool_undeclared;
    phase := 3;
    % "need_var" % tool_undeclared;
    phase := 4;
    IPers tool_undeclared, watch;
    phase := 5;
    % "need_pers" % known;
  ERROR
    TEST phase
    CASE 1:
      TPWrite "direct ERR_REFUNKDAT=" \Bool:=ERRNO = ERR_REFUNKDAT;
    CASE 2:
      TPWrite "late ERR_REFUNKDAT=" \Bool:=ERRNO = ERR_REFUNKDAT;
    CASE 3:
      TPWrite "late VAR ERR_REFUNKDAT=" \Bool:=ERRNO = ERR_REFUNKDAT;
    CASE 4:
      TPWrite "installed ERR_REFUNKDAT=" \Bool:=ERRNO = ERR_REFUNKDAT;
    CASE 5:
      TPWrite "declared variable ERR_ARGNOTPER=" \Bool:=ERRNO = ERR_ARGNOTPER;
    ENDTEST
    TRYNEXT;
  ENDPROC
ENDMODULE
