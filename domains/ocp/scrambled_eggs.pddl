; foon2pddl, encoding ocp, level 3: 10 of 101 units after relevance pruning
; goal: scrambled eggs (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-b03b810a)
  (:requirements :strips)
  (:constants
    air
    black_pepper
    bowl
    butter
    carton
    egg
    egg_mixture
    frying_pan
    milk
    plate
    salt
    scrambled_eggs
    spatula
    stove
    table
    whisk
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
    (is-ground ?o)  ; ?o is ground
    (is-whole ?o)  ; ?o is whole
  )

  (:action crack_17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (in bowl air)
      (under bowl table)
      (on table bowl)
      (is-whole egg)
      (under egg table)
      (on table egg)
    )
    :effect (and
      (in bowl egg)
      (under egg bowl)
      (is-whole egg)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )

  (:action pour_milk_19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl egg)
      (under egg bowl)
      (in carton milk)
      (under milk carton)
    )
    :effect (and
      (in bowl milk)
      (under milk bowl)
      (under egg bowl)
      (in carton milk)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action sprinkle_salt_20
    ; unit 20: sprinkle from 03-scrambled_eggs.foon:37
    ; sprinkle: bowl (contains {egg, milk}), salt (granulated), black pepper (ground) -> bowl (contains {black pepper, egg, milk, salt}), salt (in [bowl]), black pepper (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under salt table)
      (on table salt)
      (is-ground black_pepper)
      (under black_pepper table)
      (on table black_pepper)
    )
    :effect (and
      (in bowl salt)
      (under salt bowl)
      (in bowl black_pepper)
      (under black_pepper bowl)
      (is-ground black_pepper)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action mix_ingredients_21
    ; unit 21: mix from 03-scrambled_eggs.foon:51
    ; mix: bowl (contains {black pepper, egg, milk, salt}), egg (beaten, in [bowl]), milk (in [bowl]), salt (in [bowl]), black pepper (in [bowl]), whisk -> bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, i...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl egg)
      (under egg bowl)
      (in bowl milk)
      (under milk bowl)
      (in bowl salt)
      (under salt bowl)
      (in bowl black_pepper)
      (under black_pepper bowl)
      (under whisk table)
      (on table whisk)
    )
    :effect (and
      (in bowl egg_mixture)
      (under egg_mixture bowl)
      (under egg bowl)
      (under milk bowl)
      (under salt bowl)
      (under black_pepper bowl)
      (under bowl table)
      (on table bowl)
      (under whisk table)
      (on table whisk)
    )
  )

  (:action pick-and-place_frying_pan_22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (in frying_pan air)
      (under frying_pan table)
      (on table frying_pan)
      (under stove table)
      (on table stove)
    )
    :effect (and
      (on stove frying_pan)
      (under frying_pan stove)
      (on table frying_pan)
      (under stove table)
      (on table stove)
      (in frying_pan air)
    )
  )

  (:action pick-and-place_butter_24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (in frying_pan air)
      (on stove frying_pan)
      (under frying_pan stove)
      (under butter table)
      (on table butter)
    )
    :effect (and
      (in frying_pan butter)
      (under butter frying_pan)
      (on table butter)
      (on stove frying_pan)
      (under frying_pan stove)
      (not (in frying_pan air))
    )
  )

  (:action pour_26
    ; unit 26: pour from 03-scrambled_eggs.foon:109
    ; pour: bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, in [bowl]), frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan (contains {butter, egg mixture}, on [stove...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl egg_mixture)
      (under egg_mixture bowl)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan butter)
      (under butter frying_pan)
    )
    :effect (and
      (in frying_pan egg_mixture)
      (under egg_mixture frying_pan)
      (under bowl table)
      (on table bowl)
      (in bowl egg_mixture)
      (under butter frying_pan)
      (on stove frying_pan)
      (under frying_pan stove)
    )
  )

  (:action stir_ingredients_27
    ; unit 27: stir from 03-scrambled_eggs.foon:128
    ; stir: stove (on), frying pan (contains {butter, egg mixture}, on [stove]), egg mixture (contains {black pepper, egg, milk, salt}, in [frying pan]), spatula -> frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in...
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan egg_mixture)
      (under egg_mixture frying_pan)
      (under spatula table)
      (on table spatula)
    )
    :effect (and
      (in frying_pan scrambled_eggs)
      (under scrambled_eggs frying_pan)
      (under stove table)
      (under egg_mixture frying_pan)
      (on stove frying_pan)
      (under frying_pan stove)
      (under spatula table)
      (on table spatula)
    )
  )

  (:action scoop_plate_28
    ; unit 28: scoop from 03-scrambled_eggs.foon:146
    ; scoop: frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {scrambled eggs}), scrambled eggs (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan scrambled_eggs)
      (under scrambled_eggs frying_pan)
      (under spatula table)
      (on table spatula)
      (on plate air)
      (under plate table)
      (on table plate)
    )
    :effect (and
      (on plate scrambled_eggs)
      (under scrambled_eggs plate)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan scrambled_eggs)
      (under spatula table)
      (on table spatula)
      (under plate table)
      (on table plate)
      (not (on plate air))
    )
  )

  (:action sprinkle_salt_76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under salt table)
      (on table salt)
    )
    :effect (and
      (in bowl salt)
      (under salt bowl)
      (under bowl table)
      (on table bowl)
    )
  )
)
