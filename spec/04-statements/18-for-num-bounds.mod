MODULE for_num_bounds
! @format 2
! @section 4.18
! @expect ok
! @description Section 4.18's example FOR i FROM 10 TO 1 STEP -1, and bounds that are num expressions.
  VAR num a{10};
  VAR num b{10};
  VAR num n := 3;
  PROC main()
    FOR i FROM 10 TO 1 STEP -1 DO
      a{i} := b{i};
    ENDFOR
    FOR k FROM n TO n * 2 STEP 0.5 DO
      n := k;
    ENDFOR
  ENDPROC
ENDMODULE
