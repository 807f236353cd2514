/* Gc_pacing's access to the major collector of OCaml 4.13 (gc_pacing.mli says why). */
#define CAML_INTERNALS
#include <caml/mlvalues.h>
#include <caml/major_gc.h>

value rapid_sem_gc_idle(value unit)
{
  (void) unit;
  return Val_bool(caml_gc_phase == Phase_idle);
}

/* The work counted towards the next slices: words allocated in the major heap, custom blocks'
   memory, the ring of work already spread over the coming slices and its credit. */
value rapid_sem_gc_forget_pace(value unit)
{
  int i;
  (void) unit;
  caml_allocated_words = 0;
  caml_extra_heap_resources = 0.0;
  for (i = 0; i < Max_major_window; i++) caml_major_ring[i] = 0.0;
  caml_major_work_credit = 0.0;
  return Val_unit;
}
