!rapid-sem: --io cell.io --entry main
MODULE BadDirective
  PROC test_nothing()
  ENDPROC
ENDMODULE
