type ('k, 'v) t = { slots : ('k * 'v) option array; mutable next : int; mutable count : int }

let create n = { slots = Array.make (max 1 n) None; next = 0; count = 0 }

let add t k v =
  let n = Array.length t.slots in
  t.slots.(t.next) <- Some (k, v);
  t.next <- (t.next + 1) mod n;
  t.count <- min n (t.count + 1)

let find_opt t k =
  let n = Array.length t.slots in
  let rec go i =
    if i >= t.count then None
    else match t.slots.((t.next - 1 - i + 2 * n) mod n) with
      | Some (k', v) when k' = k -> Some v
      | _ -> go (i + 1) in
  go 0
