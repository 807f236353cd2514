MODULE stub_unmodelled
! @format 3
! @section 13
! @section 2.22
! @options stub-unmodelled
! @expect ok
! @description Under rapid-sem's --stub-unmodelled (doc/rulings.md R-13-i) an installed routine it does not model runs as a no-op: a procedure does nothing and leaves its VAR and INOUT arguments as they were (answer keeps its value), a function returns the initial value of its result type (§2.22: 0 for RunMode's symnum, FALSE for IsSysId, "" for Type), and the run goes on to its end (exit 0). TPReadFK is called twice, and warned about once.
! @output answer: 7
! @output speed: 0
! @output another system
! @output type: ""
! @output answer: 7
! @output done
! @exit 0
  VAR num answer := 7;
  VAR num speed := 7;
  VAR string kind := "none";
  PROC main()
    FOR i FROM 1 TO 2 DO
      TPReadFK answer, "Go on?", "Yes", "No", "", "", "";
      TPWrite "answer: " \Num:=answer;
      IF i = 1 THEN
        speed := RunMode();
        TPWrite "speed: " \Num:=speed;
        IF IsSysId("6400-1234") THEN
          TPWrite "that system";
        ELSE
          TPWrite "another system";
        ENDIF
        kind := Type(answer);
        TPWrite "type: """ + kind + """";
      ENDIF
    ENDFOR
    TPWrite "done";
  ENDPROC
ENDMODULE
