; foon2pddl, encoding instances, level 3: 15 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 17 (baking powder 1, butter 1, egg 1, flour 1, frying pan 1, ladle 1, maple syrup 1, milk 1, mixing bowl 1, pancake 1, pancake batter 1, plate 1, salt 1, spatula 1, stove 1, sugar 1, whisk 1)
; lanes: each instance changes state only as in the unfolded plan
; subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)
(define (domain foon-instances-c999fb47)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
  )
  (:constants
    not-yet-made - object-state
    baking_powder_in_mixing_bowl - object-state
    baking_powder_powder - object-state
    butter_in_frying_pan_melted - object-state
    butter_in_frying_pan_solid - object-state
    butter_solid - object-state
    egg_cracked_in_mixing_bowl - object-state
    egg_whole - object-state
    flour_in_mixing_bowl - object-state
    flour_powder - object-state
    frying_pan_contains_butter_on_stove - object-state
    frying_pan_contains_butter_pancake_batter_on_stove - object-state
    frying_pan_contains_pancake_on_stove - object-state
    frying_pan_empty - object-state
    frying_pan_empty_on_stove - object-state
    ladle_plain - object-state
    maple_syrup_in_bottle - object-state
    maple_syrup_on_pancake - object-state
    milk_in_carton - object-state
    milk_in_mixing_bowl - object-state
    mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar - object-state
    mixing_bowl_contains_baking_powder_egg_flour_salt_sugar - object-state
    mixing_bowl_contains_baking_powder_flour_salt_sugar - object-state
    mixing_bowl_contains_flour - object-state
    mixing_bowl_contains_heavy_cream - object-state
    mixing_bowl_contains_heavy_cream_sugar - object-state
    mixing_bowl_contains_pancake_batter - object-state
    mixing_bowl_empty - object-state
    pancake_cooked_in_frying_pan - object-state
    pancake_cooked_on_plate - object-state
    pancake_cooked_on_plate_topped_maple_syrup - object-state
    pancake_half-cooked_in_frying_pan - object-state
    pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan - object-state
    pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl - object-state
    plate_contains_maple_syrup_pancake - object-state
    plate_contains_pancake - object-state
    plate_empty - object-state
    salt_granulated - object-state
    salt_in_mixing_bowl - object-state
    spatula_plain - object-state
    stove_off - object-state
    stove_on - object-state
    sugar_granulated - object-state
    sugar_in_mixing_bowl - object-state
    whisk_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
    (lane ?x - physical-object ?s - object-state ?t - object-state)  ; static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)
    (together ?a - physical-object ?b - physical-object)  ; static: ?a and ?b change state in one firing of the unfolded plan
    (type_baking_powder ?x - physical-object)  ; ?x is of type baking_powder
    (type_butter ?x - physical-object)  ; ?x is of type butter
    (type_egg ?x - physical-object)  ; ?x is of type egg
    (type_flour ?x - physical-object)  ; ?x is of type flour
    (type_frying_pan ?x - physical-object)  ; ?x is of type frying_pan
    (type_ladle ?x - physical-object)  ; ?x is of type ladle
    (type_maple_syrup ?x - physical-object)  ; ?x is of type maple_syrup
    (type_milk ?x - physical-object)  ; ?x is of type milk
    (type_mixing_bowl ?x - physical-object)  ; ?x is of type mixing_bowl
    (type_pancake ?x - physical-object)  ; ?x is of type pancake
    (type_pancake_batter ?x - physical-object)  ; ?x is of type pancake_batter
    (type_plate ?x - physical-object)  ; ?x is of type plate
    (type_salt ?x - physical-object)  ; ?x is of type salt
    (type_spatula ?x - physical-object)  ; ?x is of type spatula
    (type_stove ?x - physical-object)  ; ?x is of type stove
    (type_sugar ?x - physical-object)  ; ?x is of type sugar
    (type_whisk ?x - physical-object)  ; ?x is of type whisk
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters (?mixing_bowl - physical-object ?sugar - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_sugar ?sugar)
      (together ?mixing_bowl ?sugar)
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (lane ?mixing_bowl mixing_bowl_contains_heavy_cream mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_granulated)
      (lane ?sugar sugar_granulated sugar_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (occupied mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream))
      (not (is ?sugar sugar_granulated))
    )
  )

  (:action pick-and-place_u22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters (?frying_pan - physical-object ?stove - physical-object)
    :precondition (and
      (type_frying_pan ?frying_pan)
      (type_stove ?stove)
      (is ?frying_pan frying_pan_empty)
      (lane ?frying_pan frying_pan_empty frying_pan_empty_on_stove)
      (is ?stove stove_off)
      (lane ?stove stove_off stove_off)
    )
    :effect (and
      (is ?frying_pan frying_pan_empty_on_stove)
      (not (is ?frying_pan frying_pan_empty))
    )
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters (?stove - physical-object)
    :precondition (and
      (type_stove ?stove)
      (is ?stove stove_off)
      (lane ?stove stove_off stove_on)
    )
    :effect (and
      (is ?stove stove_on)
      (occupied stove_on)
      (not (is ?stove stove_off))
    )
  )

  (:action pick-and-place_u24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters (?frying_pan - physical-object ?butter - physical-object)
    :precondition (and
      (type_frying_pan ?frying_pan)
      (type_butter ?butter)
      (together ?frying_pan ?butter)
      (is ?frying_pan frying_pan_empty_on_stove)
      (lane ?frying_pan frying_pan_empty_on_stove frying_pan_contains_butter_on_stove)
      (is ?butter butter_solid)
      (lane ?butter butter_solid butter_in_frying_pan_solid)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (is ?butter butter_in_frying_pan_solid)
      (not (is ?frying_pan frying_pan_empty_on_stove))
      (not (is ?butter butter_solid))
    )
  )

  (:action melt_u25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters (?butter - physical-object)
    :precondition (and
      (type_butter ?butter)
      (occupied stove_on)
      (is ?butter butter_in_frying_pan_solid)
      (lane ?butter butter_in_frying_pan_solid butter_in_frying_pan_melted)
    )
    :effect (and
      (is ?butter butter_in_frying_pan_melted)
      (occupied butter_in_frying_pan_melted)
      (not (is ?butter butter_in_frying_pan_solid))
    )
  )

  (:action pour_u29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters (?mixing_bowl - physical-object ?flour - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_flour ?flour)
      (together ?mixing_bowl ?flour)
      (is ?mixing_bowl mixing_bowl_empty)
      (lane ?mixing_bowl mixing_bowl_empty mixing_bowl_contains_flour)
      (is ?flour flour_powder)
      (lane ?flour flour_powder flour_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_flour)
      (is ?flour flour_in_mixing_bowl)
      (occupied flour_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_empty))
      (not (is ?flour flour_powder))
    )
  )

  (:action pour_u30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters (?mixing_bowl - physical-object ?baking_powder - physical-object ?sugar - physical-object ?salt - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_baking_powder ?baking_powder)
      (type_sugar ?sugar)
      (type_salt ?salt)
      (together ?mixing_bowl ?baking_powder)
      (together ?baking_powder ?sugar)
      (together ?sugar ?salt)
      (is ?mixing_bowl mixing_bowl_contains_flour)
      (lane ?mixing_bowl mixing_bowl_contains_flour mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (is ?baking_powder baking_powder_powder)
      (lane ?baking_powder baking_powder_powder baking_powder_in_mixing_bowl)
      (is ?sugar sugar_granulated)
      (lane ?sugar sugar_granulated sugar_in_mixing_bowl)
      (is ?salt salt_granulated)
      (lane ?salt salt_granulated salt_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (is ?baking_powder baking_powder_in_mixing_bowl)
      (occupied baking_powder_in_mixing_bowl)
      (is ?sugar sugar_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (is ?salt salt_in_mixing_bowl)
      (occupied salt_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_flour))
      (not (is ?baking_powder baking_powder_powder))
      (not (is ?sugar sugar_granulated))
      (not (is ?salt salt_granulated))
    )
  )

  (:action crack_u31
    ; unit 31: crack from 04-pancakes.foon:31
    ; crack: mixing bowl (contains {baking powder, flour, salt, sugar}), egg (whole) -> mixing bowl (contains {baking powder, egg, flour, salt, sugar}), egg (cracked, in [mixing bowl])
    :parameters (?mixing_bowl - physical-object ?egg - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_egg ?egg)
      (together ?mixing_bowl ?egg)
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (lane ?mixing_bowl mixing_bowl_contains_baking_powder_flour_salt_sugar mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
      (is ?egg egg_whole)
      (lane ?egg egg_whole egg_cracked_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
      (is ?egg egg_cracked_in_mixing_bowl)
      (occupied egg_cracked_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_baking_powder_flour_salt_sugar))
      (not (is ?egg egg_whole))
    )
  )

  (:action pour_u32
    ; unit 32: pour from 04-pancakes.foon:42
    ; pour: mixing bowl (contains {baking powder, egg, flour, salt, sugar}), milk (in [carton]) -> mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), milk (in [mixing bowl])
    :parameters (?mixing_bowl - physical-object ?milk - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_milk ?milk)
      (together ?mixing_bowl ?milk)
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
      (lane ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_salt_sugar mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
      (is ?milk milk_in_carton)
      (lane ?milk milk_in_carton milk_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
      (is ?milk milk_in_mixing_bowl)
      (occupied milk_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_salt_sugar))
      (not (is ?milk milk_in_carton))
    )
  )

  (:action whisk_u33
    ; unit 33: whisk from 04-pancakes.foon:52
    ; whisk: mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), flour (in [mixing bowl]), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixing bowl]), egg (cracked, in [mixing bowl]), milk (in [mixin...
    :parameters (?mixing_bowl - physical-object ?pancake_batter - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_pancake_batter ?pancake_batter)
      (together ?mixing_bowl ?pancake_batter)
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
      (lane ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar mixing_bowl_contains_pancake_batter)
      (occupied flour_in_mixing_bowl)
      (occupied baking_powder_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (occupied salt_in_mixing_bowl)
      (occupied egg_cracked_in_mixing_bowl)
      (occupied milk_in_mixing_bowl)
      (occupied whisk_plain)
      (is ?pancake_batter not-yet-made)
      (lane ?pancake_batter not-yet-made pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_pancake_batter)
      (occupied mixing_bowl_contains_pancake_batter)
      (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar))
      (not (is ?pancake_batter not-yet-made))
    )
  )

  (:action pour_u34
    ; unit 34: pour from 04-pancakes.foon:114
    ; pour: mixing bowl (contains {pancake batter}), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [mixing bowl]), ladle, frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan ...
    :parameters (?pancake_batter - physical-object ?frying_pan - physical-object)
    :precondition (and
      (type_pancake_batter ?pancake_batter)
      (type_frying_pan ?frying_pan)
      (together ?pancake_batter ?frying_pan)
      (occupied mixing_bowl_contains_pancake_batter)
      (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
      (lane ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
      (occupied ladle_plain)
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (lane ?frying_pan frying_pan_contains_butter_on_stove frying_pan_contains_butter_pancake_batter_on_stove)
      (occupied butter_in_frying_pan_melted)
    )
    :effect (and
      (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
      (occupied pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
      (is ?frying_pan frying_pan_contains_butter_pancake_batter_on_stove)
      (not (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl))
      (not (is ?frying_pan frying_pan_contains_butter_on_stove))
    )
  )

  (:action cook_u35
    ; unit 35: cook from 04-pancakes.foon:135
    ; cook: stove (on), frying pan (contains {butter, pancake batter}, on [stove]), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [frying pan]) -> frying pan (contains {pancake}, on [stove]), pancake (half-cooked,...
    :parameters (?frying_pan - physical-object ?pancake - physical-object)
    :precondition (and
      (type_frying_pan ?frying_pan)
      (type_pancake ?pancake)
      (together ?frying_pan ?pancake)
      (occupied stove_on)
      (is ?frying_pan frying_pan_contains_butter_pancake_batter_on_stove)
      (lane ?frying_pan frying_pan_contains_butter_pancake_batter_on_stove frying_pan_contains_pancake_on_stove)
      (occupied pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
      (is ?pancake not-yet-made)
      (lane ?pancake not-yet-made pancake_half-cooked_in_frying_pan)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_pancake_on_stove)
      (occupied frying_pan_contains_pancake_on_stove)
      (is ?pancake pancake_half-cooked_in_frying_pan)
      (not (is ?frying_pan frying_pan_contains_butter_pancake_batter_on_stove))
      (not (is ?pancake not-yet-made))
    )
  )

  (:action flip_u36
    ; unit 36: flip from 04-pancakes.foon:151
    ; flip: pancake (half-cooked, in [frying pan]), spatula -> pancake (cooked, in [frying pan]), spatula
    :parameters (?pancake - physical-object)
    :precondition (and
      (type_pancake ?pancake)
      (is ?pancake pancake_half-cooked_in_frying_pan)
      (lane ?pancake pancake_half-cooked_in_frying_pan pancake_cooked_in_frying_pan)
      (occupied spatula_plain)
    )
    :effect (and
      (is ?pancake pancake_cooked_in_frying_pan)
      (not (is ?pancake pancake_half-cooked_in_frying_pan))
    )
  )

  (:action pick-and-place_u37
    ; unit 37: pick-and-place from 04-pancakes.foon:161
    ; pick-and-place: frying pan (contains {pancake}, on [stove]), pancake (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {pancake}), pancake (cooked, on [plate]), spatula
    :parameters (?pancake - physical-object ?plate - physical-object)
    :precondition (and
      (type_pancake ?pancake)
      (type_plate ?plate)
      (together ?pancake ?plate)
      (occupied frying_pan_contains_pancake_on_stove)
      (is ?pancake pancake_cooked_in_frying_pan)
      (lane ?pancake pancake_cooked_in_frying_pan pancake_cooked_on_plate)
      (occupied spatula_plain)
      (is ?plate plate_empty)
      (lane ?plate plate_empty plate_contains_pancake)
    )
    :effect (and
      (is ?pancake pancake_cooked_on_plate)
      (is ?plate plate_contains_pancake)
      (not (is ?pancake pancake_cooked_in_frying_pan))
      (not (is ?plate plate_empty))
    )
  )

  (:action pour_u38
    ; unit 38: pour from 04-pancakes.foon:178
    ; pour: plate (contains {pancake}), pancake (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {maple syrup, pancake}), pancake (cooked, on [plate], topped {maple syrup}), maple syrup (on [pancake])
    :parameters (?plate - physical-object ?pancake - physical-object ?maple_syrup - physical-object)
    :precondition (and
      (type_plate ?plate)
      (type_pancake ?pancake)
      (type_maple_syrup ?maple_syrup)
      (together ?plate ?pancake)
      (together ?pancake ?maple_syrup)
      (is ?plate plate_contains_pancake)
      (lane ?plate plate_contains_pancake plate_contains_maple_syrup_pancake)
      (is ?pancake pancake_cooked_on_plate)
      (lane ?pancake pancake_cooked_on_plate pancake_cooked_on_plate_topped_maple_syrup)
      (is ?maple_syrup maple_syrup_in_bottle)
      (lane ?maple_syrup maple_syrup_in_bottle maple_syrup_on_pancake)
    )
    :effect (and
      (is ?plate plate_contains_maple_syrup_pancake)
      (occupied plate_contains_maple_syrup_pancake)
      (is ?pancake pancake_cooked_on_plate_topped_maple_syrup)
      (occupied pancake_cooked_on_plate_topped_maple_syrup)
      (is ?maple_syrup maple_syrup_on_pancake)
      (occupied maple_syrup_on_pancake)
      (not (is ?plate plate_contains_pancake))
      (not (is ?pancake pancake_cooked_on_plate))
      (not (is ?maple_syrup maple_syrup_in_bottle))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: pancake (cooked, on [plate], topped {maple syrup})
    :parameters ()
    :precondition (and
      (occupied pancake_cooked_on_plate_topped_maple_syrup)
    )
    :effect (and
      (goal-reached)
    )
  )
)
