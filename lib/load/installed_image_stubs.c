/* The installed environment in the executable's data (lib/load/gen/static_image.ml lays it out
   in installed_image_blob.c): what start-up takes instead of reading marshalled bytes.

   Its blocks are outside the heap, as OCaml's own static data is. The page table is told they
   are static data, so that comparison, hashing and Marshal treat them as values, and the
   collector neither marks nor sweeps them. They may still be changed (a table of the checker's
   state that grows): a young value stored in one goes through caml_modify and is in the
   minor collector's remembered set; for the major collector and the compactor, a roots hook
   passes every field of the image that points outside it, as a module's globals are passed. */
#define CAML_INTERNALS
#include <stdint.h>
#include <caml/mlvalues.h>
#include <caml/memory.h>
#include <caml/address_class.h>
#include <caml/roots.h>
#include <caml/minor_gc.h>
#include <caml/fail.h>

extern uintptr_t rapid_sem_image_words[];
extern const uintptr_t rapid_sem_image_root;
extern const int rapid_sem_image_atom_count;
extern const uint32_t rapid_sem_image_atoms[];
extern const int rapid_sem_image_scanned_count;
extern const uint32_t rapid_sem_image_scanned[];
extern const int rapid_sem_image_word_count;

static int ready = 0;
static void (*previous_hook)(scanning_action) = NULL;

static int in_image(value v)
{
  uintptr_t start = (uintptr_t) rapid_sem_image_words;
  return (uintptr_t) v - start < (uintptr_t) rapid_sem_image_word_count * sizeof(uintptr_t);
}

static void scan_image(scanning_action f)
{
  int k;
  mlsize_t i;
  if (previous_hook != NULL) previous_hook(f);
  /* the minor collector finds the young values stored here in its remembered set */
  if (f == caml_oldify_one) return;
  for (k = 0; k < rapid_sem_image_scanned_count; k++) {
    value v = (value) (rapid_sem_image_words + rapid_sem_image_scanned[k] + 1);
    mlsize_t n = Wosize_val(v);
    for (i = 0; i < n; i++) {
      value x = Field(v, i);
      if (Is_block(x) && !in_image(x)) f(x, &Field(v, i));
    }
  }
}

value rapid_sem_installed_image(value unit)
{
  (void) unit;
  if (!ready) {
    int k;
    if (caml_page_table_add(In_static_data, rapid_sem_image_words,
                            rapid_sem_image_words + rapid_sem_image_word_count) != 0)
      caml_raise_out_of_memory();
    for (k = 0; k < rapid_sem_image_atom_count; k++)
      rapid_sem_image_words[rapid_sem_image_atoms[2 * k]] = (uintptr_t) Atom(rapid_sem_image_atoms[2 * k + 1]);
    previous_hook = caml_scan_roots_hook;
    caml_scan_roots_hook = scan_image;
    ready = 1;
  }
  return (value) rapid_sem_image_root;
}
