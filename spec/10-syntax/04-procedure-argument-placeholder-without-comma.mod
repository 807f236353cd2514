MODULE procedure_argument_placeholder_w
! @section 4.6
! @expect syntax-error 6:9
! @description After the first argument <ARG> is preceded by ','.
  PROC main()
    p 1 <ARG>;
  ENDPROC
ENDMODULE
