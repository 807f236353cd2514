MODULE placeholder_statement
! @format 3
! @section 1.2
! @section 2.9
! @section 4.1
! @expect ok
! @description A program with placeholders runs, but executing the placeholder <SMT> is an execution error, ERR_EXECPHR (section 1.2, chapter 12), at the placeholder.
! @output before
! @exit 1
! @error ERR_EXECPHR 13:5
  PROC main()
    TPWrite "before";
    <SMT>
    TPWrite "after";
  ENDPROC
ENDMODULE
