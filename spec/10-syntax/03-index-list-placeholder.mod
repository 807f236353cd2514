MODULE index_list_placeholder
! @section 3.6
! @expect syntax-error 8:12
! @description <index list> holds <expr>s: <EXP> is not one.
  VAR num x;
  VAR num a{2};
  PROC main()
    x := a{<EXP>};
  ENDPROC
ENDMODULE
