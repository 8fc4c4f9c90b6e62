; foon2pddl, encoding instances, level 3: 14 of 101 units after relevance pruning
; goal: scrambled eggs (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 14 (black pepper 1, bowl 1, butter 1, egg 1, egg mixture 1, fork 1, frying pan 1, milk 1, plate 1, salt 1, scrambled eggs 1, spatula 1, stove 1, whisk 1)
; lanes: each instance changes state only as in the unfolded plan
; subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)
(define (domain foon-instances-93c19915)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
  )
  (:constants
    not-yet-made - object-state
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
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
    (lane ?x - physical-object ?s - object-state ?t - object-state)  ; static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)
    (together ?a - physical-object ?b - physical-object)  ; static: ?a and ?b change state in one firing of the unfolded plan
    (type_black_pepper ?x - physical-object)  ; ?x is of type black_pepper
    (type_bowl ?x - physical-object)  ; ?x is of type bowl
    (type_butter ?x - physical-object)  ; ?x is of type butter
    (type_egg ?x - physical-object)  ; ?x is of type egg
    (type_egg_mixture ?x - physical-object)  ; ?x is of type egg_mixture
    (type_fork ?x - physical-object)  ; ?x is of type fork
    (type_frying_pan ?x - physical-object)  ; ?x is of type frying_pan
    (type_milk ?x - physical-object)  ; ?x is of type milk
    (type_plate ?x - physical-object)  ; ?x is of type plate
    (type_salt ?x - physical-object)  ; ?x is of type salt
    (type_scrambled_eggs ?x - physical-object)  ; ?x is of type scrambled_eggs
    (type_spatula ?x - physical-object)  ; ?x is of type spatula
    (type_stove ?x - physical-object)  ; ?x is of type stove
    (type_whisk ?x - physical-object)  ; ?x is of type whisk
  )

  (:action crack_u17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters (?bowl - physical-object ?egg - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_egg ?egg)
      (together ?bowl ?egg)
      (is ?bowl bowl_empty)
      (lane ?bowl bowl_empty bowl_contains_egg)
      (is ?egg egg_whole)
      (lane ?egg egg_whole egg_cracked_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_egg)
      (is ?egg egg_cracked_in_bowl)
      (not (is ?bowl bowl_empty))
      (not (is ?egg egg_whole))
    )
  )

  (:action beat_u18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters (?egg - physical-object)
    :precondition (and
      (type_egg ?egg)
      (is ?egg egg_cracked_in_bowl)
      (lane ?egg egg_cracked_in_bowl egg_beaten_in_bowl)
      (occupied whisk_plain)
    )
    :effect (and
      (is ?egg egg_beaten_in_bowl)
      (occupied egg_beaten_in_bowl)
      (not (is ?egg egg_cracked_in_bowl))
    )
  )

  (:action pour_u19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters (?bowl - physical-object ?milk - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_milk ?milk)
      (together ?bowl ?milk)
      (is ?bowl bowl_contains_egg)
      (lane ?bowl bowl_contains_egg bowl_contains_egg_milk)
      (occupied egg_beaten_in_bowl)
      (is ?milk milk_in_carton)
      (lane ?milk milk_in_carton milk_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_egg_milk)
      (is ?milk milk_in_bowl)
      (occupied milk_in_bowl)
      (not (is ?bowl bowl_contains_egg))
      (not (is ?milk milk_in_carton))
    )
  )

  (:action sprinkle_u20
    ; unit 20: sprinkle from 03-scrambled_eggs.foon:37
    ; sprinkle: bowl (contains {egg, milk}), salt (granulated), black pepper (ground) -> bowl (contains {black pepper, egg, milk, salt}), salt (in [bowl]), black pepper (in [bowl])
    :parameters (?bowl - physical-object ?salt - physical-object ?black_pepper - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_salt ?salt)
      (type_black_pepper ?black_pepper)
      (together ?bowl ?salt)
      (together ?salt ?black_pepper)
      (is ?bowl bowl_contains_egg_milk)
      (lane ?bowl bowl_contains_egg_milk bowl_contains_black_pepper_egg_milk_salt)
      (is ?salt salt_granulated)
      (lane ?salt salt_granulated salt_in_bowl)
      (is ?black_pepper black_pepper_ground)
      (lane ?black_pepper black_pepper_ground black_pepper_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_black_pepper_egg_milk_salt)
      (is ?salt salt_in_bowl)
      (occupied salt_in_bowl)
      (is ?black_pepper black_pepper_in_bowl)
      (occupied black_pepper_in_bowl)
      (not (is ?bowl bowl_contains_egg_milk))
      (not (is ?salt salt_granulated))
      (not (is ?black_pepper black_pepper_ground))
    )
  )

  (:action mix_u21
    ; unit 21: mix from 03-scrambled_eggs.foon:51
    ; mix: bowl (contains {black pepper, egg, milk, salt}), egg (beaten, in [bowl]), milk (in [bowl]), salt (in [bowl]), black pepper (in [bowl]), whisk -> bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, i...
    :parameters (?bowl - physical-object ?egg_mixture - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_egg_mixture ?egg_mixture)
      (together ?bowl ?egg_mixture)
      (is ?bowl bowl_contains_black_pepper_egg_milk_salt)
      (lane ?bowl bowl_contains_black_pepper_egg_milk_salt bowl_contains_egg_mixture)
      (occupied egg_beaten_in_bowl)
      (occupied milk_in_bowl)
      (occupied salt_in_bowl)
      (occupied black_pepper_in_bowl)
      (occupied whisk_plain)
      (is ?egg_mixture not-yet-made)
      (lane ?egg_mixture not-yet-made egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_egg_mixture)
      (occupied bowl_contains_egg_mixture)
      (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
      (not (is ?bowl bowl_contains_black_pepper_egg_milk_salt))
      (not (is ?egg_mixture not-yet-made))
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

  (:action pour_u26
    ; unit 26: pour from 03-scrambled_eggs.foon:109
    ; pour: bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, in [bowl]), frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan (contains {butter, egg mixture}, on [stove...
    :parameters (?egg_mixture - physical-object ?frying_pan - physical-object)
    :precondition (and
      (type_egg_mixture ?egg_mixture)
      (type_frying_pan ?frying_pan)
      (together ?egg_mixture ?frying_pan)
      (occupied bowl_contains_egg_mixture)
      (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
      (lane ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (lane ?frying_pan frying_pan_contains_butter_on_stove frying_pan_contains_butter_egg_mixture_on_stove)
      (occupied butter_in_frying_pan_melted)
    )
    :effect (and
      (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (occupied egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (is ?frying_pan frying_pan_contains_butter_egg_mixture_on_stove)
      (not (is ?egg_mixture egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl))
      (not (is ?frying_pan frying_pan_contains_butter_on_stove))
    )
  )

  (:action stir_u27
    ; unit 27: stir from 03-scrambled_eggs.foon:128
    ; stir: stove (on), frying pan (contains {butter, egg mixture}, on [stove]), egg mixture (contains {black pepper, egg, milk, salt}, in [frying pan]), spatula -> frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in...
    :parameters (?frying_pan - physical-object ?scrambled_eggs - physical-object)
    :precondition (and
      (type_frying_pan ?frying_pan)
      (type_scrambled_eggs ?scrambled_eggs)
      (together ?frying_pan ?scrambled_eggs)
      (occupied stove_on)
      (is ?frying_pan frying_pan_contains_butter_egg_mixture_on_stove)
      (lane ?frying_pan frying_pan_contains_butter_egg_mixture_on_stove frying_pan_contains_scrambled_eggs_on_stove)
      (occupied egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (occupied spatula_plain)
      (is ?scrambled_eggs not-yet-made)
      (lane ?scrambled_eggs not-yet-made scrambled_eggs_cooked_in_frying_pan)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_scrambled_eggs_on_stove)
      (occupied frying_pan_contains_scrambled_eggs_on_stove)
      (is ?scrambled_eggs scrambled_eggs_cooked_in_frying_pan)
      (not (is ?frying_pan frying_pan_contains_butter_egg_mixture_on_stove))
      (not (is ?scrambled_eggs not-yet-made))
    )
  )

  (:action scoop_u28
    ; unit 28: scoop from 03-scrambled_eggs.foon:146
    ; scoop: frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {scrambled eggs}), scrambled eggs (cooked, on [plate]), spatula
    :parameters (?scrambled_eggs - physical-object ?plate - physical-object)
    :precondition (and
      (type_scrambled_eggs ?scrambled_eggs)
      (type_plate ?plate)
      (together ?scrambled_eggs ?plate)
      (occupied frying_pan_contains_scrambled_eggs_on_stove)
      (is ?scrambled_eggs scrambled_eggs_cooked_in_frying_pan)
      (lane ?scrambled_eggs scrambled_eggs_cooked_in_frying_pan scrambled_eggs_cooked_on_plate)
      (occupied spatula_plain)
      (is ?plate plate_empty)
      (lane ?plate plate_empty plate_contains_scrambled_eggs)
    )
    :effect (and
      (is ?scrambled_eggs scrambled_eggs_cooked_on_plate)
      (occupied scrambled_eggs_cooked_on_plate)
      (is ?plate plate_contains_scrambled_eggs)
      (occupied plate_contains_scrambled_eggs)
      (not (is ?scrambled_eggs scrambled_eggs_cooked_in_frying_pan))
      (not (is ?plate plate_empty))
    )
  )

  (:action beat_u39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters (?egg - physical-object)
    :precondition (and
      (type_egg ?egg)
      (is ?egg egg_cracked_in_bowl)
      (lane ?egg egg_cracked_in_bowl egg_beaten_in_bowl)
      (occupied fork_plain)
    )
    :effect (and
      (is ?egg egg_beaten_in_bowl)
      (occupied egg_beaten_in_bowl)
      (not (is ?egg egg_cracked_in_bowl))
    )
  )

  (:action sprinkle_u76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters (?bowl - physical-object ?salt - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_salt ?salt)
      (together ?bowl ?salt)
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (lane ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is ?salt salt_granulated)
      (lane ?salt salt_granulated salt_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (occupied bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is ?salt salt_in_bowl)
      (occupied salt_in_bowl)
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
