type pos = { x : float; y : float; z : float }
type orient = { q1 : float; q2 : float; q3 : float; q4 : float }
type t = { trans : pos; rot : orient }
