rs_test(test_material unit SOURCES unit/test_material.c
        CASES pfeiffer_is_tangent_of_stack_law hakiel_polynomial table_monotone tube_core_is_lame recipes
              modulus_of_stresses strain_steps_batched)
