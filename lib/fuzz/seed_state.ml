(* Stdlib's [Random.State.make] digests its seed 110 times, each time writing a seed element
   with [Int.to_string] (the C printf: some 900 instructions) before the MD5: three states a
   program were about 5 % of a campaign's instructions, the decimal writing half of that
   (bench/README.md, "What each program still re-did"). This is the same computation (OCaml
   4.13's random.ml, full_init) with each element written once. The state is that module's
   record, which the library does not let one build: the representation is checked against
   [Random.State.make] by test/test_campaign.ml on thousands of seeds, and anything else than
   OCaml 4.13's layout would fail it. *)

type layout = { st : int array; mutable idx : int }

let extract d =
  Char.code (String.unsafe_get d 0) + (Char.code (String.unsafe_get d 1) lsl 8)
  + (Char.code (String.unsafe_get d 2) lsl 16) + (Char.code (String.unsafe_get d 3) lsl 24)

let make seed =
  let seed = if Array.length seed = 0 then [| 0 |] else seed in
  let l = Array.length seed in
  let texts = Array.map Int.to_string seed in
  let st = Array.init 55 (fun i -> i) in
  (* [accu ^ text] is written into one buffer, the digest over its first bytes: the 110
     concatenations were a sixth of the states' cost. The first accumulator is "x", one byte;
     every later one a digest of 16. *)
  let longest = Array.fold_left (fun m t -> Int.max m (String.length t)) 0 texts in
  let buffer = Bytes.create (16 + longest) in
  Bytes.unsafe_set buffer 0 'x';
  let accu_length = ref 1 and accu = ref "x" in
  for i = 0 to 54 + Int.max 55 l do
    let j = i mod 55 in
    let text = Array.unsafe_get texts (i mod l) in
    Bytes.unsafe_blit_string text 0 buffer !accu_length (String.length text);
    accu := Digest.subbytes buffer 0 (!accu_length + String.length text);
    Bytes.unsafe_blit_string !accu 0 buffer 0 16;
    accu_length := 16;
    Array.unsafe_set st j ((Array.unsafe_get st j lxor extract !accu) land 0x3FFFFFFF)
  done;
  (Obj.magic ({ st; idx = 0 } : layout) : Random.State.t)
