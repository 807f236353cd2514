mem mem-chapter16.mod
