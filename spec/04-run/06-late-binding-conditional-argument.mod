MODULE late_conditional_argument
! @format 3
! @section 4.6
! @section 3.11
! @expect ok
! @description A conditional argument of a late-bound call passes on an optional parameter (section 3.11): present when it is, absent otherwise; a conditional argument for a required parameter raises ERR_CALLPROC; two conditional arguments for alternatives of one optional parameter that are both present raise ERR_ARGDUPCND.
! @output present 5
! @output absent
! @output conditional for required: 
! @output callproc
! @output alternatives both present: 
! @output argdupcnd
! @exit 0
  PROC inner(\num n)
    IF Present(n) THEN
      TPWrite "present " \Num:=n;
    ELSE
      TPWrite "absent";
    ENDIF
  ENDPROC
  PROC needs(num n)
    TPWrite "wrong";
  ENDPROC
  PROC outer(\num n)
    % "inner" % \n ? n;
  ENDPROC
  PROC outer_required(\num n)
    % "needs" % \n ? n;
  ENDPROC
  PROC either(\num speed | num time)
    TPWrite "wrong";
  ENDPROC
  PROC outer_both(\num a, \num b)
    % "either" % \speed ? a \time ? b;
  ENDPROC
  PROC main()
    outer \n:=5;
    outer;
    TPWrite "conditional for required: ";
    outer_required \n:=5;
    TPWrite "alternatives both present: ";
    outer_both \a:=1 \b:=2;
  ERROR
    IF ERRNO = ERR_CALLPROC THEN
      TPWrite "callproc";
      TRYNEXT;
    ELSEIF ERRNO = ERR_ARGDUPCND THEN
      TPWrite "argdupcnd";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
