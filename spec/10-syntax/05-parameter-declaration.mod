MODULE parameter_declaration
! @section 5.2
! @expect ok
! @description <parameter declaration>: access modes, switch, conformant arrays, <DIM>, <ID>; the array parameters of section 5.2.
  PROC p(num a, VAR num b, PERS num c, INOUT num d, switch s,
         VAR num e{*}, num f{*, *}, PERS num g{*, *, *}, num h{<DIM>}, <ID> <ID>)
  ENDPROC
  PROC arrmul( VAR num array{*}, num factor)
  ENDPROC
  PROC pallets(VAR num pallet{*,*})
    ! num-matrix parameter
  ENDPROC
ENDMODULE
