MODULE function_call_late_bound
! @section 3.11
! @section 4.6
! @expect syntax-error 8:10
! @description Late binding is for procedure calls only; a function is named by an identifier.
  VAR num x;
  PROC main()
    x := % "f" %(1);
  ENDPROC
ENDMODULE
