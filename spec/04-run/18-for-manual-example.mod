MODULE for_manual_example
! @format 3
! @section 4.18
! @expect ok
! @description Section 4.18's example FOR i FROM 10 TO 1 STEP -1 DO a{i} := b{i}; copies every element, from the last to the first.
! @output 10
! @output 1
! @output 55
! @exit 0
  VAR num a{10};
  VAR num b{10} := [1, 2, 3, 4, 5, 6, 7, 8, 9, 10];
  VAR num sum;
  PROC main()
    FOR i FROM 10 TO 1 STEP -1 DO
      a{i} := b{i};
    ENDFOR
    TPWrite "" \Num:=a{10};
    TPWrite "" \Num:=a{1};
    FOR i FROM 1 TO 10 DO
      sum := sum + a{i};
    ENDFOR
    TPWrite "" \Num:=sum;
  ENDPROC
ENDMODULE
