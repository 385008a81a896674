/* The creep state's vector operations (creep_vector.c) */
#ifndef REELSIM_STORAGE_CREEP_VECTOR_H
#define REELSIM_STORAGE_CREEP_VECTOR_H

#include <sundials/sundials_nvector.h>

/* replaces the hot operations of v (and of every vector cloned from it afterwards) */
void rs_creep_vector_specialise(N_Vector v);

#endif
