MODULE placeholder_var
! @section 2.9
! @section 4.5
! @section 4.6
! @section 4.15
! @expect ok
! @description <VAR> stands for a data object reference: assignment target, connect target, conditional argument.
  VAR num temp;
  PROC main()
    <VAR> := temp + 5;
    CONNECT <VAR> WITH t;
    p \a ? <VAR>;
  ENDPROC
  TRAP t
  ENDTRAP
ENDMODULE
