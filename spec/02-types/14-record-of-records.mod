MODULE record_of_records
! @format 2
! @section 2.14
! @expect ok
! @description A component may be of a record type (built-in or defined in the module): components are reached through several levels.
  RECORD segment
    pos start;
    pos stop;
  ENDRECORD
  RECORD track
    segment first;
    segment second;
    num count;
  ENDRECORD
  VAR track tr;
  PROC main()
    tr.first.stop.x := 1;
    tr.second := [[0, 0, 0], [1, 1, 1]];
    tr := [[[0, 0, 0], [1, 0, 0]], [[1, 0, 0], [2, 0, 0]], 2];
  ENDPROC
ENDMODULE
