; foon2pddl, encoding relational, level 3: 14 of 101 units after relevance pruning
; goal: french toast (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 20 (bowl 2, bread 1, butter 1, cinnamon 1, custard 1, egg 2, fork 1, french toast 1, frying pan 1, maple syrup 2, milk 2, plate 1, spatula 1, stove 2, vanilla extract 1)
; objects: 2 x bowl (empty): in the plan the counts are derived from (FOON's, unfolded), each of crack at 03-scrambled_eggs.foon:3 x2 takes one out of that state and no unit puts one back
; objects: 2 x egg (whole): in the plan the counts are derived from (FOON's, unfolded), each of crack at 03-scrambled_eggs.foon:3 x2 takes one out of that state and no unit puts one back
; objects: 2 x stove (off): in the plan the counts are derived from (FOON's, unfolded), each of turn on at 03-scrambled_eggs.foon:80 takes one out of that state and no unit puts one back; one stays for a unit that only reads it
; label mismatch: 05-french_toast.foon:175: plate lists maple syrup, which the unit puts on [french toast]
(define (problem make_french_toast)
  (:domain foon-relational-6d0af126)
  (:objects
    bowl_1 - bowl
    bowl_2 - bowl
    bread_1 - bread
    butter_1 - butter
    cinnamon_1 - cinnamon
    custard_1 - custard
    egg_1 - egg
    egg_2 - egg
    fork_1 - fork
    french_toast_1 - french_toast
    frying_pan_1 - frying_pan
    maple_syrup_1 - maple_syrup
    maple_syrup_2 - maple_syrup
    milk_1 - milk
    milk_2 - milk
    plate_1 - plate
    spatula_1 - spatula
    stove_1 - stove
    stove_2 - stove
    vanilla_extract_1 - vanilla_extract
    bottle_1 - bottle
    carton_1 - carton
  )
  (:init
    (in bottle_1 maple_syrup_1)
    (in carton_1 milk_1)
    (is bottle_1 bottle_contains_maple_syrup)
    (is bowl_1 bowl_empty)
    (is bowl_2 bowl_empty)
    (is bread_1 bread_sliced)
    (is butter_1 butter_solid)
    (is carton_1 carton_contains_milk)
    (is cinnamon_1 cinnamon_ground)
    (is custard_1 not-yet-made)
    (is egg_1 egg_whole)
    (is egg_2 egg_whole)
    (is fork_1 fork_plain)
    (is french_toast_1 not-yet-made)
    (is frying_pan_1 frying_pan_empty)
    (is maple_syrup_1 maple_syrup_in_bottle)
    (is maple_syrup_2 not-yet-made)
    (is milk_1 milk_in_carton)
    (is milk_2 not-yet-made)
    (is plate_1 plate_empty)
    (is spatula_1 spatula_plain)
    (is stove_1 stove_off)
    (is stove_2 stove_off)
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
