let file = ref (Source.register ~name:"<none>" ~line_starts:[| 0 |])

exception Refused of Source.region * string
