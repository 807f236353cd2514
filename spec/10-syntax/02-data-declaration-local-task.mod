MODULE data_declaration_local_task
! @section 2.18
! @expect syntax-error 5:9
! @description LOCAL and TASK are alternatives; they do not combine.
  LOCAL TASK VAR num c;
ENDMODULE
