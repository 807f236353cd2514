MODULE inomax_a
! @format 4
! @task T_ROB1
! @section 4.15
! @section 8
! @section 14
! @expect ok
! @description The limit of 100 interrupt numbers is per task (installed-facts.md section 6, "100 per task"; doc/rulings.md R-8-i): task A holds 100 and its 101st CONNECT raises ERR_INOMAX; task B, later, still gets 100 numbers of its own, and then ERR_INOMAX too.
! @output A connected 100 ERR_INOMAX TRUE
! @output B connected 100 ERR_INOMAX TRUE
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
    TPWrite "A connected " + NumToStr(n, 0) + " ERR_INOMAX " \Bool:=(ERRNO = ERR_INOMAX);
    WaitTime 2;
    RETURN;
  ENDPROC
ENDMODULE
