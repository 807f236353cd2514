MODULE space_inside_compound_delimiter
! @section 2.2
! @section 2.8
! @expect syntax-error 8:9
! @description Tokens are indivisible: ": =" is a colon (ending the label x) and an equals sign, not ":=".
  VAR num x;
  PROC main()
    x : = 1;
  ENDPROC
ENDMODULE
