MODULE aggregate_trailing_comma
! @section 3.10
! @expect syntax-error 7:20
! @description Each ',' in an aggregate is followed by an <expr>.
  VAR pos p;
  PROC main()
    p := [1, 2, 3, ];
  ENDPROC
ENDMODULE
