MODULE retry_elseif_condition
! @format 3
! @section 4.13
! @section 4.16
! @section 7.1
! @expect ok
! @description An error in an ELSEIF condition: the statement that caused it is the IF statement the ELSEIF belongs to, so RETRY executes the whole IF again, its first condition included (section 4.13: "the statement that caused the error is executed again").
! @output first 1
! @output second 1
! @output handler
! @output first 2
! @output second 2
! @output elseif
! @exit 0
  VAR num firsts;
  VAR num seconds;
  FUNC bool first()
    firsts := firsts + 1;
    TPWrite "first " \Num:=firsts;
    RETURN FALSE;
  ENDFUNC
  FUNC bool second()
    seconds := seconds + 1;
    TPWrite "second " \Num:=seconds;
    IF seconds = 1 RAISE 7;
    RETURN TRUE;
  ENDFUNC
  PROC main()
    IF first() THEN
      TPWrite "then";
    ELSEIF second() THEN
      TPWrite "elseif";
    ELSE
      TPWrite "else";
    ENDIF
  ERROR
    TPWrite "handler";
    RETRY;
  ENDPROC
ENDMODULE
