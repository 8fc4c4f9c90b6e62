; foon2pddl, encoding relational, level 3: 14 of 101 units after relevance pruning
; goal: french toast (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 17 (bowl 1, bread 1, butter 1, cinnamon 1, custard 1, egg 1, fork 1, french toast 1, frying pan 1, maple syrup 2, milk 2, plate 1, spatula 1, stove 1, vanilla extract 1)
; label mismatch: 05-french_toast.foon:175: plate lists maple syrup, which the unit puts on [french toast]
(define (problem make_french_toast)
  (:domain foon-relational-c1573858)
  (:objects
    bowl_1 - bowl
    bread_1 - bread
    butter_1 - butter
    cinnamon_1 - cinnamon
    custard_1 - custard
    egg_1 - egg
    french_toast_1 - french_toast
    frying_pan_1 - frying_pan
    maple_syrup_2 - maple_syrup
    milk_2 - milk
    plate_1 - plate
    stove_1 - stove
    vanilla_extract_1 - vanilla_extract
  )
  (:init
    (is bowl_1 bowl_empty)
    (is bread_1 bread_sliced)
    (is butter_1 butter_solid)
    (is cinnamon_1 cinnamon_ground)
    (is custard_1 not-yet-made)
    (is egg_1 egg_whole)
    (is french_toast_1 not-yet-made)
    (is frying_pan_1 frying_pan_empty)
    (is maple_syrup_2 not-yet-made)
    (is milk_2 not-yet-made)
    (is plate_1 plate_empty)
    (is stove_1 stove_off)
    (is vanilla_extract_1 vanilla_extract_liquid)
    (occupied bottle_contains_maple_syrup)
    (occupied carton_contains_milk)
    (occupied fork_plain)
    (occupied maple_syrup_in_bottle)
    (occupied milk_in_carton)
    (occupied spatula_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
