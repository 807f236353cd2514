MODULE record_two_trailing_strict
! @section 2.10
! @expect syntax-error 8:5
! @options strict
! @description In strict mode, only the last line may hold a comment alone: of two trailing comment lines the first is refused.
  RECORD r
    num a;
    ! alone, followed by another comment line
    ! alone on the last line
  ENDRECORD
ENDMODULE
