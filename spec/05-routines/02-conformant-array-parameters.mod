MODULE conformant_array_parameters
! @format 2
! @section 5.2
! @section 5.4
! @expect ok
! @description Section 5.4's arrmul with a {*} parameter and Dim, called with arrays of different sizes; {*,*} and {*,*,*} parameters.
  VAR num short{3};
  VAR num long{12};
  VAR pos pallet{2, 5};
  VAR num cube{2, 2, 2};
  PROC arrmul(VAR num array{*}, num factor)
    FOR index FROM 1 TO Dim(array, 1) DO
      array{index} := array{index} * factor;
    ENDFOR
  ENDPROC
  PROC clear_pallet(VAR pos pallet{*,*})
  ENDPROC
  PROC sum(num values{*,*,*})
  ENDPROC
  PROC main()
    arrmul short, 2;
    arrmul long, 0.5;
    clear_pallet pallet;
    sum cube;
  ENDPROC
ENDMODULE
