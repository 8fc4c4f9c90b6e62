; foon2pddl, encoding relational, level 3: 15 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 19 (baking powder 1, butter 1, egg 1, flour 1, frying pan 1, ladle 1, maple syrup 2, milk 2, mixing bowl 1, pancake 1, pancake batter 1, plate 1, salt 1, spatula 1, stove 1, sugar 1, whisk 1)
; label mismatch: 04-pancakes.foon:178: plate lists maple syrup, which the unit puts on [pancake]
(define (problem make_pancake)
  (:domain foon-relational-5a1a3fb3)
  (:objects
    baking_powder_1 - baking_powder
    butter_1 - butter
    egg_1 - egg
    flour_1 - flour
    frying_pan_1 - frying_pan
    ladle_1 - ladle
    maple_syrup_1 - maple_syrup
    maple_syrup_2 - maple_syrup
    milk_1 - milk
    milk_2 - milk
    mixing_bowl_1 - mixing_bowl
    pancake_1 - pancake
    pancake_batter_1 - pancake_batter
    plate_1 - plate
    salt_1 - salt
    spatula_1 - spatula
    stove_1 - stove
    sugar_1 - sugar
    whisk_1 - whisk
    bottle_1 - bottle
    carton_1 - carton
  )
  (:init
    (in bottle_1 maple_syrup_1)
    (in carton_1 milk_1)
    (is baking_powder_1 baking_powder_powder)
    (is bottle_1 bottle_contains_maple_syrup)
    (is butter_1 butter_solid)
    (is carton_1 carton_contains_milk)
    (is egg_1 egg_whole)
    (is flour_1 flour_powder)
    (is frying_pan_1 frying_pan_empty)
    (is ladle_1 ladle_plain)
    (is maple_syrup_1 maple_syrup_in_bottle)
    (is maple_syrup_2 not-yet-made)
    (is milk_1 milk_in_carton)
    (is milk_2 not-yet-made)
    (is mixing_bowl_1 mixing_bowl_empty)
    (is pancake_1 not-yet-made)
    (is pancake_batter_1 not-yet-made)
    (is plate_1 plate_empty)
    (is salt_1 salt_granulated)
    (is spatula_1 spatula_plain)
    (is stove_1 stove_off)
    (is sugar_1 sugar_granulated)
    (is whisk_1 whisk_plain)
    (occupied bottle_contains_maple_syrup)
    (occupied carton_contains_milk)
    (occupied ladle_plain)
    (occupied maple_syrup_in_bottle)
    (occupied milk_in_carton)
    (occupied spatula_plain)
    (occupied whisk_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
