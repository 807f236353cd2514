MODULE continue_while
! @format 3
! @section 4.9
! @section 4.19
! @expect ok
! @description CONTINUE in a WHILE loop skips the rest of the body; the condition is evaluated again before the next iteration (section 4.19).
! @output check 0
! @output odd 1
! @output check 1
! @output check 2
! @output odd 3
! @output check 3
! @output check 4
! @exit 0
  VAR num n;
  FUNC bool more()
    TPWrite "check " \Num:=n;
    RETURN n < 4;
  ENDFUNC
  PROC main()
    WHILE more() DO
      n := n + 1;
      IF n MOD 2 = 0 CONTINUE;
      TPWrite "odd " \Num:=n;
    ENDWHILE
  ENDPROC
ENDMODULE
