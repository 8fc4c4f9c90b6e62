; foon2pddl, encoding relational, level 3: 14 of 101 units after relevance pruning
; goal: scrambled eggs (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 15 (black pepper 1, bowl 1, butter 1, egg 1, egg mixture 1, fork 1, frying pan 1, milk 2, plate 1, salt 1, scrambled eggs 1, spatula 1, stove 1, whisk 1)
(define (domain foon-relational-4ab76182)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    black_pepper - physical-object
    bowl - physical-object
    butter - physical-object
    carton - physical-object
    egg - physical-object
    egg_mixture - physical-object
    fork - physical-object
    frying_pan - physical-object
    milk - physical-object
    plate - physical-object
    salt - physical-object
    scrambled_eggs - physical-object
    spatula - physical-object
    stove - physical-object
    whisk - physical-object
  )
  (:constants
    not-yet-made - object-state
    consumed - object-state
    black_pepper_ground - object-state
    black_pepper_in_bowl - object-state
    bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato - object-state
    bowl_contains_avocado_cilantro_lime_juice_onion_tomato - object-state
    bowl_contains_black_pepper_egg_milk_salt - object-state
    bowl_contains_egg - object-state
    bowl_contains_egg_milk - object-state
    bowl_contains_egg_mixture - object-state
    bowl_empty - object-state
    butter_in_frying_pan_melted - object-state
    butter_in_frying_pan_solid - object-state
    butter_solid - object-state
    carton_contains_milk - object-state
    egg_beaten_in_bowl - object-state
    egg_cracked_in_bowl - object-state
    egg_whole - object-state
    egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl - object-state
    egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan - object-state
    fork_plain - object-state
    frying_pan_contains_butter_on_stove - object-state
    frying_pan_contains_butter_egg_mixture_on_stove - object-state
    frying_pan_contains_scrambled_eggs_on_stove - object-state
    frying_pan_empty - object-state
    frying_pan_empty_on_stove - object-state
    milk_in_bowl - object-state
    milk_in_carton - object-state
    plate_contains_scrambled_eggs - object-state
    plate_empty - object-state
    salt_granulated - object-state
    salt_in_bowl - object-state
    scrambled_eggs_cooked_in_frying_pan - object-state
    scrambled_eggs_cooked_on_plate - object-state
    spatula_plain - object-state
    stove_off - object-state
    stove_on - object-state
    whisk_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (in ?h - physical-object ?x - physical-object)  ; ?x is in ?h
    (on ?h - physical-object ?x - physical-object)  ; ?x is on ?h
    (occupied ?s - object-state)  ; some object is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
  )

  (:action crack_u17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters (?bowl - bowl ?egg - egg)
    :precondition (and
      (is ?bowl bowl_empty)
      (is ?egg egg_whole)
    )
    :effect (and
      (is ?bowl bowl_contains_egg)
      (is ?egg egg_cracked_in_bowl)
      (in ?bowl ?egg)
      (not (is ?bowl bowl_empty))
      (not (is ?egg egg_whole))
    )
  )

  (:action beat_u18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters (?egg - egg)
    :precondition (and
      (is ?egg egg_cracked_in_bowl)
      (occupied whisk_plain)
    )
    :effect (and
      (is ?egg egg_beaten_in_bowl)
      (not (is ?egg egg_cracked_in_bowl))
    )
  )

  (:action pour_u19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters (?bowl - bowl ?egg - egg ?milk_portion - milk)
    :precondition (and
      (is ?bowl bowl_contains_egg)
      (is ?egg egg_beaten_in_bowl)
      (in ?bowl ?egg)
      (is ?milk_portion not-yet-made)
      (occupied milk_in_carton)
    )
    :effect (and
      (is ?bowl bowl_contains_egg_milk)
      (is ?milk_portion milk_in_bowl)
      (in ?bowl ?milk_portion)
      (not (is ?bowl bowl_contains_egg))
      (not (is ?milk_portion not-yet-made))
    )
  )

  (:action sprinkle_u20
    ; unit 20: sprinkle from 03-scrambled_eggs.foon:37
    ; sprinkle: bowl (contains {egg, milk}), salt (granulated), black pepper (ground) -> bowl (contains {black pepper, egg, milk, salt}), salt (in [bowl]), black pepper (in [bowl])
    :parameters (?bowl - bowl ?salt - salt ?black_pepper - black_pepper)
    :precondition (and
      (is ?bowl bowl_contains_egg_milk)
      (is ?salt salt_granulated)
      (is ?black_pepper black_pepper_ground)
    )
    :effect (and
      (is ?bowl bowl_contains_black_pepper_egg_milk_salt)
      (is ?salt salt_in_bowl)
      (in ?bowl ?salt)
      (is ?black_pepper black_pepper_in_bowl)
      (in ?bowl ?black_pepper)
      (not (is ?bowl bowl_contains_egg_milk))
      (not (is ?salt salt_granulated))
      (not (is ?black_pepper black_pepper_ground))
    )
  )

  (:action mix_u21
    ; unit 21: mix from 03-scrambled_eggs.foon:51
    ; mix: bowl (contains {black pepper, egg, milk, salt}), egg (beaten, in [bowl]), milk (in [bowl]), salt (in [bowl]), black pepper (in [bowl]), whisk -> bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, i...
    :parameters (?bowl - bowl ?egg - egg ?milk - milk ?salt - salt ?black_pepper - black_pepper ?egg_mixture - egg_mixture)
    :precondition (and
      (is ?bowl bowl_contains_black_pepper_egg_milk_salt)
      (is ?egg egg_beaten_in_bowl)
      (in ?bowl ?egg)
      (is ?milk milk_in_bowl)
      (in ?bowl ?milk)
      (is ?salt salt_in_bowl)
      (in ?bowl ?salt)
      (is ?black_pepper black_pepper_in_bowl)
      (in ?bowl ?black_pepper)
      (occupied whisk_plain)
      (is ?egg_mixture not-yet-made)
    )
    :effect (and
      (is ?bowl bowl_contains_egg_mixture)
      (is ?egg consumed)
      (is ?milk consumed)
      (is ?salt consumed)
      (is ?black_pepper consumed)
      (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
      (in ?bowl ?egg_mixture)
      (not (is ?bowl bowl_contains_black_pepper_egg_milk_salt))
      (not (is ?egg egg_beaten_in_bowl))
      (not (in ?bowl ?egg))
      (not (is ?milk milk_in_bowl))
      (not (in ?bowl ?milk))
      (not (is ?salt salt_in_bowl))
      (not (in ?bowl ?salt))
      (not (is ?black_pepper black_pepper_in_bowl))
      (not (in ?bowl ?black_pepper))
      (not (is ?egg_mixture not-yet-made))
      (forall (?egg_alike - egg) (when (and (in ?bowl ?egg_alike) (is ?egg_alike egg_beaten_in_bowl)) (and (is ?egg_alike consumed) (not (in ?bowl ?egg_alike)) (not (is ?egg_alike egg_beaten_in_bowl)))))
      (forall (?egg_alike-2 - egg) (when (and (in ?bowl ?egg_alike-2) (is ?egg_alike-2 egg_cracked_in_bowl)) (and (is ?egg_alike-2 consumed) (not (in ?bowl ?egg_alike-2)) (not (is ?egg_alike-2 egg_cracked_in_bowl)))))
      (forall (?milk_alike - milk) (when (and (in ?bowl ?milk_alike) (is ?milk_alike milk_in_bowl)) (and (is ?milk_alike consumed) (not (in ?bowl ?milk_alike)) (not (is ?milk_alike milk_in_bowl)))))
      (forall (?salt_alike - salt) (when (and (in ?bowl ?salt_alike) (is ?salt_alike salt_in_bowl)) (and (is ?salt_alike consumed) (not (in ?bowl ?salt_alike)) (not (is ?salt_alike salt_in_bowl)))))
      (forall (?black_pepper_alike - black_pepper) (when (and (in ?bowl ?black_pepper_alike) (is ?black_pepper_alike black_pepper_in_bowl)) (and (is ?black_pepper_alike consumed) (not (in ?bowl ?black_pepper_alike)) (not (is ?black_pepper_alike black_pepper_in_bowl)))))
    )
  )

  (:action pick-and-place_u22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters (?frying_pan - frying_pan ?stove - stove)
    :precondition (and
      (is ?frying_pan frying_pan_empty)
      (is ?stove stove_off)
    )
    :effect (and
      (is ?frying_pan frying_pan_empty_on_stove)
      (on ?stove ?frying_pan)
      (not (is ?frying_pan frying_pan_empty))
    )
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters (?stove - stove)
    :precondition (and
      (is ?stove stove_off)
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
    :parameters (?frying_pan - frying_pan ?butter - butter)
    :precondition (and
      (is ?frying_pan frying_pan_empty_on_stove)
      (is ?butter butter_solid)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (is ?butter butter_in_frying_pan_solid)
      (in ?frying_pan ?butter)
      (not (is ?frying_pan frying_pan_empty_on_stove))
      (not (is ?butter butter_solid))
    )
  )

  (:action melt_u25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters (?butter - butter)
    :precondition (and
      (occupied stove_on)
      (is ?butter butter_in_frying_pan_solid)
    )
    :effect (and
      (is ?butter butter_in_frying_pan_melted)
      (not (is ?butter butter_in_frying_pan_solid))
    )
  )

  (:action pour_u26
    ; unit 26: pour from 03-scrambled_eggs.foon:109
    ; pour: bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, in [bowl]), frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan (contains {butter, egg mixture}, on [stove...
    :parameters (?bowl - bowl ?egg_mixture - egg_mixture ?frying_pan - frying_pan ?butter - butter)
    :precondition (and
      (is ?bowl bowl_contains_egg_mixture)
      (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
      (in ?bowl ?egg_mixture)
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (is ?butter butter_in_frying_pan_melted)
      (in ?frying_pan ?butter)
    )
    :effect (and
      (is ?bowl bowl_empty)
      (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (in ?frying_pan ?egg_mixture)
      (is ?frying_pan frying_pan_contains_butter_egg_mixture_on_stove)
      (not (is ?bowl bowl_contains_egg_mixture))
      (not (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl))
      (not (in ?bowl ?egg_mixture))
      (not (is ?frying_pan frying_pan_contains_butter_on_stove))
    )
  )

  (:action stir_u27
    ; unit 27: stir from 03-scrambled_eggs.foon:128
    ; stir: stove (on), frying pan (contains {butter, egg mixture}, on [stove]), egg mixture (contains {black pepper, egg, milk, salt}, in [frying pan]), spatula -> frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in...
    :parameters (?stove - stove ?frying_pan - frying_pan ?egg_mixture - egg_mixture ?scrambled_eggs - scrambled_eggs)
    :precondition (and
      (is ?stove stove_on)
      (is ?frying_pan frying_pan_contains_butter_egg_mixture_on_stove)
      (on ?stove ?frying_pan)
      (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (in ?frying_pan ?egg_mixture)
      (occupied spatula_plain)
      (is ?scrambled_eggs not-yet-made)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_scrambled_eggs_on_stove)
      (is ?egg_mixture consumed)
      (is ?scrambled_eggs scrambled_eggs_cooked_in_frying_pan)
      (in ?frying_pan ?scrambled_eggs)
      (not (is ?frying_pan frying_pan_contains_butter_egg_mixture_on_stove))
      (not (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan))
      (not (in ?frying_pan ?egg_mixture))
      (not (is ?scrambled_eggs not-yet-made))
      (forall (?egg_mixture_alike - egg_mixture) (when (and (in ?frying_pan ?egg_mixture_alike) (is ?egg_mixture_alike egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)) (and (is ?egg_mixture_alike consumed) (not (in ?frying_pan ?egg_mixture_alike)) (not (is ?egg_mixture_alike egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)))))
      (forall (?butter_in_it - butter) (when (and (in ?frying_pan ?butter_in_it) (is ?butter_in_it butter_in_frying_pan_melted)) (and (is ?butter_in_it consumed) (not (in ?frying_pan ?butter_in_it)) (not (is ?butter_in_it butter_in_frying_pan_melted)))))
      (forall (?butter_in_it - butter) (when (and (in ?frying_pan ?butter_in_it) (is ?butter_in_it butter_in_frying_pan_solid)) (and (is ?butter_in_it consumed) (not (in ?frying_pan ?butter_in_it)) (not (is ?butter_in_it butter_in_frying_pan_solid)))))
    )
  )

  (:action scoop_u28
    ; unit 28: scoop from 03-scrambled_eggs.foon:146
    ; scoop: frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {scrambled eggs}), scrambled eggs (cooked, on [plate]), spatula
    :parameters (?frying_pan - frying_pan ?scrambled_eggs - scrambled_eggs ?plate - plate)
    :precondition (and
      (is ?frying_pan frying_pan_contains_scrambled_eggs_on_stove)
      (is ?scrambled_eggs scrambled_eggs_cooked_in_frying_pan)
      (in ?frying_pan ?scrambled_eggs)
      (occupied spatula_plain)
      (is ?plate plate_empty)
    )
    :effect (and
      (is ?frying_pan frying_pan_empty_on_stove)
      (is ?scrambled_eggs scrambled_eggs_cooked_on_plate)
      (occupied scrambled_eggs_cooked_on_plate)
      (on ?plate ?scrambled_eggs)
      (is ?plate plate_contains_scrambled_eggs)
      (occupied plate_contains_scrambled_eggs)
      (not (is ?frying_pan frying_pan_contains_scrambled_eggs_on_stove))
      (not (is ?scrambled_eggs scrambled_eggs_cooked_in_frying_pan))
      (not (in ?frying_pan ?scrambled_eggs))
      (not (is ?plate plate_empty))
    )
  )

  (:action beat_u39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters (?egg - egg)
    :precondition (and
      (is ?egg egg_cracked_in_bowl)
      (occupied fork_plain)
    )
    :effect (and
      (is ?egg egg_beaten_in_bowl)
      (not (is ?egg egg_cracked_in_bowl))
    )
  )

  (:action sprinkle_u76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters (?bowl - bowl ?salt - salt)
    :precondition (and
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (is ?salt salt_granulated)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (occupied bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is ?salt salt_in_bowl)
      (in ?bowl ?salt)
      (not (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato))
      (not (is ?salt salt_granulated))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: scrambled eggs (cooked, on [plate])
    :parameters ()
    :precondition (and
      (occupied scrambled_eggs_cooked_on_plate)
    )
    :effect (and
      (goal-reached)
    )
  )
)
