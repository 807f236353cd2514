MODULE placeholder_rdn
! @section 2.9
! @section 5.1
! @expect ok
! @description <RDN> stands for a routine declaration.
  VAR num x;
  <RDN>
  PROC main()
  ENDPROC
  <RDN>
ENDMODULE
