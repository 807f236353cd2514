MODULE aggregate_wrong_component_count
! @format 2
! @section 2.17
! @section 3.10
! @expect semantic-error 7:16
! @description An aggregate with two members for pos (three components) has another structure; refused at the aggregate.
  VAR pos p := [1, 2];
ENDMODULE
