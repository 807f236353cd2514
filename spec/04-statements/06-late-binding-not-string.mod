MODULE late_binding_not_string
! @format 2
! @section 4.6
! @expect semantic-error 8:7
! @description The expression of a late-bound call is of type string; a num is refused at the expression.
  VAR num product_id := 2;
  PROC main()
    % product_id %;
  ENDPROC
ENDMODULE
