; foon2pddl, encoding relational, level 3: 15 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 19 (baking powder 1, butter 1, egg 1, flour 1, frying pan 1, ladle 1, maple syrup 2, milk 2, mixing bowl 1, pancake 1, pancake batter 1, plate 1, salt 1, spatula 1, stove 1, sugar 1, whisk 1)
; label mismatch: 04-pancakes.foon:178: plate lists maple syrup, which the unit puts on [pancake]
(define (problem make_pancake)
  (:domain foon-relational-d6420c02)
  (:objects
    baking_powder_1 - baking_powder
    butter_1 - butter
    egg_1 - egg
    flour_1 - flour
    frying_pan_1 - frying_pan
    maple_syrup_2 - maple_syrup
    milk_2 - milk
    mixing_bowl_1 - mixing_bowl
    pancake_1 - pancake
    pancake_batter_1 - pancake_batter
    plate_1 - plate
    salt_1 - salt
    stove_1 - stove
    sugar_1 - sugar
  )
  (:init
    (is baking_powder_1 baking_powder_powder)
    (is butter_1 butter_solid)
    (is egg_1 egg_whole)
    (is flour_1 flour_powder)
    (is frying_pan_1 frying_pan_empty)
    (is maple_syrup_2 not-yet-made)
    (is milk_2 not-yet-made)
    (is mixing_bowl_1 mixing_bowl_empty)
    (is pancake_1 not-yet-made)
    (is pancake_batter_1 not-yet-made)
    (is plate_1 plate_empty)
    (is salt_1 salt_granulated)
    (is stove_1 stove_off)
    (is sugar_1 sugar_granulated)
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
