MODULE unknown_data_type
! @format 2
! @section 2.11
! @expect semantic-error 7:7
! @description A data type name that is neither built in, installed nor defined in the task is refused at the type name.
  VAR num n;
  VAR widget w;
ENDMODULE
