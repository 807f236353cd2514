MODULE for_statement
! @section 4.18
! @expect ok
! @description The example of section 4.18, FOR without STEP, and placeholders in a FOR statement.
  VAR num a{10};
  VAR num b{10};
  PROC main()
    FOR i FROM 10 TO 1 STEP -1 DO
      a{i} := b{i};
    ENDFOR
    FOR j FROM 1 TO 3 DO
    ENDFOR
    FOR <ID> FROM <EXP> TO <EXP> STEP <EXP> DO
    ENDFOR
  ENDPROC
ENDMODULE
