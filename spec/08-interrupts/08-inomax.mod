MODULE inomax
! @format 3
! @section 4.15
! @section 8
! @expect ok
! @statement-time 0
! @description A task holds at most 100 interrupt numbers (installed-facts.md section 6): the 101st CONNECT raises ERR_INOMAX.
! @output connected 100
! @output ERR_INOMAX TRUE
  VAR intnum ints{101};
  VAR num n := 0;
  TRAP t
  ENDTRAP
  PROC main()
    FOR i FROM 1 TO 101 DO
      CONNECT ints{i} WITH t;
      n := n + 1;
    ENDFOR
  ERROR
    TPWrite "connected " \Num:=n;
    TPWrite "ERR_INOMAX " \Bool:=(ERRNO = ERR_INOMAX);
    RETURN;
  ENDPROC
ENDMODULE
