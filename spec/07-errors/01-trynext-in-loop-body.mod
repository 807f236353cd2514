MODULE trynext_in_loop_body
! @format 3
! @section 4.14
! @section 4.18
! @expect ok
! @description An error in a statement of a loop body: TRYNEXT continues with the next statement of that body, and the loop goes on.
! @output 1: 10
! @output 2: handler
! @output 2: next
! @output 3: 5
! @exit 0
  VAR num d{3} := [1, 0, 2];
  PROC main()
    VAR num x;
    FOR i FROM 1 TO 3 DO
      x := 10 / d{i};
      IF d{i} = 0 THEN
        TPWrite NumToStr(i, 0) + ": next";
      ELSE
        TPWrite NumToStr(i, 0) + ": " + NumToStr(x, 0);
      ENDIF
    ENDFOR
  ERROR
    TPWrite "2: handler";
    TRYNEXT;
  ENDPROC
ENDMODULE
