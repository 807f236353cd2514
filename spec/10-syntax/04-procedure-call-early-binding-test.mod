MODULE procedure_call_early_binding_tes
! @section 4.6
! @expect ok
! @description The early binding example of section 4.6, its elided CASE 3 completed.
  VAR num x;
  VAR num y;
  VAR num z;
  VAR num product_id := 1;
  PROC main()
    TEST product_id
    CASE 1:
      proc1 x, y, z;
    CASE 2:
      proc2 x, y, z;
    CASE 3:
      proc3 x, y, z;
    ENDTEST
  ENDPROC
ENDMODULE
