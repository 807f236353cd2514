MODULE station
  VAR num b_count;
ENDMODULE
