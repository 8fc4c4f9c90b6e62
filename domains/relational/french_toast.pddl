; foon2pddl, encoding relational, level 3: 14 of 101 units after relevance pruning
; goal: french toast (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 17 (bowl 1, bread 1, butter 1, cinnamon 1, custard 1, egg 1, fork 1, french toast 1, frying pan 1, maple syrup 2, milk 2, plate 1, spatula 1, stove 1, vanilla extract 1)
; label mismatch: 05-french_toast.foon:175: plate lists maple syrup, which the unit puts on [french toast]
(define (domain foon-relational-c1573858)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    bottle - physical-object
    bowl - physical-object
    bread - physical-object
    butter - physical-object
    carton - physical-object
    cinnamon - physical-object
    custard - physical-object
    egg - physical-object
    fork - physical-object
    french_toast - physical-object
    frying_pan - physical-object
    maple_syrup - physical-object
    milk - physical-object
    plate - physical-object
    spatula - physical-object
    stove - physical-object
    vanilla_extract - physical-object
  )
  (:constants
    not-yet-made - object-state
    consumed - object-state
    bottle_contains_maple_syrup - object-state
    bowl_contains_cinnamon_egg_milk_vanilla_extract - object-state
    bowl_contains_custard - object-state
    bowl_contains_egg - object-state
    bowl_contains_egg_milk - object-state
    bowl_empty - object-state
    bread_in_frying_pan_sliced_soaked_custard - object-state
    bread_sliced - object-state
    bread_sliced_soaked_custard - object-state
    butter_in_frying_pan_melted - object-state
    butter_in_frying_pan_solid - object-state
    butter_solid - object-state
    carton_contains_milk - object-state
    cinnamon_ground - object-state
    cinnamon_in_bowl - object-state
    custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl - object-state
    custard_contains_cinnamon_egg_milk_vanilla_extract_in_bread - object-state
    egg_beaten_in_bowl - object-state
    egg_cracked_in_bowl - object-state
    egg_whole - object-state
    fork_plain - object-state
    french_toast_cooked_in_frying_pan - object-state
    french_toast_cooked_on_plate - object-state
    french_toast_cooked_on_plate_topped_maple_syrup - object-state
    frying_pan_contains_bread_butter_on_stove - object-state
    frying_pan_contains_butter_on_stove - object-state
    frying_pan_contains_french_toast_on_stove - object-state
    frying_pan_empty - object-state
    frying_pan_empty_on_stove - object-state
    maple_syrup_in_bottle - object-state
    maple_syrup_on_french_toast - object-state
    milk_in_bowl - object-state
    milk_in_carton - object-state
    plate_contains_french_toast - object-state
    plate_contains_french_toast_maple_syrup - object-state
    plate_empty - object-state
    spatula_plain - object-state
    stove_off - object-state
    stove_on - object-state
    vanilla_extract_in_bowl - object-state
    vanilla_extract_liquid - object-state
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

  (:action pour_u40
    ; unit 40: pour* from 05-french_toast.foon:37
    ; pour: bowl (contains {egg, milk}), cinnamon (ground), vanilla extract (liquid) -> bowl (contains {cinnamon, egg, milk, vanilla extract}), cinnamon (in [bowl]), vanilla extract (in [bowl])
    :parameters (?bowl - bowl ?cinnamon - cinnamon ?vanilla_extract - vanilla_extract)
    :precondition (and
      (is ?bowl bowl_contains_egg_milk)
      (is ?cinnamon cinnamon_ground)
      (is ?vanilla_extract vanilla_extract_liquid)
    )
    :effect (and
      (is ?bowl bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (is ?cinnamon cinnamon_in_bowl)
      (in ?bowl ?cinnamon)
      (is ?vanilla_extract vanilla_extract_in_bowl)
      (in ?bowl ?vanilla_extract)
      (not (is ?bowl bowl_contains_egg_milk))
      (not (is ?cinnamon cinnamon_ground))
      (not (is ?vanilla_extract vanilla_extract_liquid))
    )
  )

  (:action mix_u41
    ; unit 41: mix from 05-french_toast.foon:51
    ; mix: bowl (contains {cinnamon, egg, milk, vanilla extract}), egg (beaten, in [bowl]), milk (in [bowl]), cinnamon (in [bowl]), vanilla extract (in [bowl]), fork -> bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla...
    :parameters (?bowl - bowl ?egg - egg ?milk - milk ?cinnamon - cinnamon ?vanilla_extract - vanilla_extract ?custard - custard)
    :precondition (and
      (is ?bowl bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (is ?egg egg_beaten_in_bowl)
      (in ?bowl ?egg)
      (is ?milk milk_in_bowl)
      (in ?bowl ?milk)
      (is ?cinnamon cinnamon_in_bowl)
      (in ?bowl ?cinnamon)
      (is ?vanilla_extract vanilla_extract_in_bowl)
      (in ?bowl ?vanilla_extract)
      (occupied fork_plain)
      (is ?custard not-yet-made)
    )
    :effect (and
      (is ?bowl bowl_contains_custard)
      (is ?egg consumed)
      (is ?milk consumed)
      (is ?cinnamon consumed)
      (is ?vanilla_extract consumed)
      (is ?custard custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
      (in ?bowl ?custard)
      (not (is ?bowl bowl_contains_cinnamon_egg_milk_vanilla_extract))
      (not (is ?egg egg_beaten_in_bowl))
      (not (in ?bowl ?egg))
      (not (is ?milk milk_in_bowl))
      (not (in ?bowl ?milk))
      (not (is ?cinnamon cinnamon_in_bowl))
      (not (in ?bowl ?cinnamon))
      (not (is ?vanilla_extract vanilla_extract_in_bowl))
      (not (in ?bowl ?vanilla_extract))
      (not (is ?custard not-yet-made))
      (forall (?egg_alike - egg) (when (and (in ?bowl ?egg_alike) (is ?egg_alike egg_beaten_in_bowl)) (and (is ?egg_alike consumed) (not (in ?bowl ?egg_alike)) (not (is ?egg_alike egg_beaten_in_bowl)))))
      (forall (?egg_alike-2 - egg) (when (and (in ?bowl ?egg_alike-2) (is ?egg_alike-2 egg_cracked_in_bowl)) (and (is ?egg_alike-2 consumed) (not (in ?bowl ?egg_alike-2)) (not (is ?egg_alike-2 egg_cracked_in_bowl)))))
      (forall (?milk_alike - milk) (when (and (in ?bowl ?milk_alike) (is ?milk_alike milk_in_bowl)) (and (is ?milk_alike consumed) (not (in ?bowl ?milk_alike)) (not (is ?milk_alike milk_in_bowl)))))
      (forall (?cinnamon_alike - cinnamon) (when (and (in ?bowl ?cinnamon_alike) (is ?cinnamon_alike cinnamon_in_bowl)) (and (is ?cinnamon_alike consumed) (not (in ?bowl ?cinnamon_alike)) (not (is ?cinnamon_alike cinnamon_in_bowl)))))
      (forall (?vanilla_extract_alike - vanilla_extract) (when (and (in ?bowl ?vanilla_extract_alike) (is ?vanilla_extract_alike vanilla_extract_in_bowl)) (and (is ?vanilla_extract_alike consumed) (not (in ?bowl ?vanilla_extract_alike)) (not (is ?vanilla_extract_alike vanilla_extract_in_bowl)))))
    )
  )

  (:action dip_u42
    ; unit 42: dip from 05-french_toast.foon:71
    ; dip: bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla extract}, in [bowl]), bread (sliced) -> bread (sliced, soaked {custard})
    :parameters (?bowl - bowl ?custard - custard ?bread - bread)
    :precondition (and
      (is ?bowl bowl_contains_custard)
      (is ?custard custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
      (in ?bowl ?custard)
      (is ?bread bread_sliced)
    )
    :effect (and
      (is ?bowl bowl_empty)
      (is ?custard custard_contains_cinnamon_egg_milk_vanilla_extract_in_bread)
      (in ?bread ?custard)
      (is ?bread bread_sliced_soaked_custard)
      (not (is ?bowl bowl_contains_custard))
      (not (is ?custard custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl))
      (not (in ?bowl ?custard))
      (not (is ?bread bread_sliced))
    )
  )

  (:action pick-and-place_u43
    ; unit 43: pick-and-place from 05-french_toast.foon:121
    ; pick-and-place: frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted), bread (sliced, soaked {custard}) -> frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard})
    :parameters (?frying_pan - frying_pan ?butter - butter ?bread - bread)
    :precondition (and
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (is ?butter butter_in_frying_pan_melted)
      (in ?frying_pan ?butter)
      (is ?bread bread_sliced_soaked_custard)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_bread_butter_on_stove)
      (is ?bread bread_in_frying_pan_sliced_soaked_custard)
      (in ?frying_pan ?bread)
      (not (is ?frying_pan frying_pan_contains_butter_on_stove))
      (not (is ?bread bread_sliced_soaked_custard))
    )
  )

  (:action fry_u44
    ; unit 44: fry from 05-french_toast.foon:139
    ; fry: stove (on), frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard}), spatula -> frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula
    :parameters (?stove - stove ?frying_pan - frying_pan ?bread - bread ?french_toast - french_toast)
    :precondition (and
      (is ?stove stove_on)
      (is ?frying_pan frying_pan_contains_bread_butter_on_stove)
      (on ?stove ?frying_pan)
      (is ?bread bread_in_frying_pan_sliced_soaked_custard)
      (in ?frying_pan ?bread)
      (occupied spatula_plain)
      (is ?french_toast not-yet-made)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_french_toast_on_stove)
      (is ?bread consumed)
      (is ?french_toast french_toast_cooked_in_frying_pan)
      (in ?frying_pan ?french_toast)
      (not (is ?frying_pan frying_pan_contains_bread_butter_on_stove))
      (not (is ?bread bread_in_frying_pan_sliced_soaked_custard))
      (not (in ?frying_pan ?bread))
      (not (is ?french_toast not-yet-made))
      (forall (?custard_in_bread - custard) (when (and (in ?bread ?custard_in_bread) (is ?custard_in_bread custard_contains_cinnamon_egg_milk_vanilla_extract_in_bread)) (and (is ?custard_in_bread consumed) (not (in ?bread ?custard_in_bread)) (not (is ?custard_in_bread custard_contains_cinnamon_egg_milk_vanilla_extract_in_bread)))))
      (forall (?bread_alike - bread) (when (and (in ?frying_pan ?bread_alike) (is ?bread_alike bread_in_frying_pan_sliced_soaked_custard)) (and (is ?bread_alike consumed) (not (in ?frying_pan ?bread_alike)) (not (is ?bread_alike bread_in_frying_pan_sliced_soaked_custard)))))
      (forall (?butter_in_it - butter) (when (and (in ?frying_pan ?butter_in_it) (is ?butter_in_it butter_in_frying_pan_melted)) (and (is ?butter_in_it consumed) (not (in ?frying_pan ?butter_in_it)) (not (is ?butter_in_it butter_in_frying_pan_melted)))))
      (forall (?butter_in_it - butter) (when (and (in ?frying_pan ?butter_in_it) (is ?butter_in_it butter_in_frying_pan_solid)) (and (is ?butter_in_it consumed) (not (in ?frying_pan ?butter_in_it)) (not (is ?butter_in_it butter_in_frying_pan_solid)))))
    )
  )

  (:action pick-and-place_u45
    ; unit 45: pick-and-place from 05-french_toast.foon:158
    ; pick-and-place: frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {french toast}), french toast (cooked, on [plate]), spatula
    :parameters (?frying_pan - frying_pan ?french_toast - french_toast ?plate - plate)
    :precondition (and
      (is ?frying_pan frying_pan_contains_french_toast_on_stove)
      (is ?french_toast french_toast_cooked_in_frying_pan)
      (in ?frying_pan ?french_toast)
      (occupied spatula_plain)
      (is ?plate plate_empty)
    )
    :effect (and
      (is ?frying_pan frying_pan_empty_on_stove)
      (is ?french_toast french_toast_cooked_on_plate)
      (on ?plate ?french_toast)
      (is ?plate plate_contains_french_toast)
      (not (is ?frying_pan frying_pan_contains_french_toast_on_stove))
      (not (is ?french_toast french_toast_cooked_in_frying_pan))
      (not (in ?frying_pan ?french_toast))
      (not (is ?plate plate_empty))
    )
  )

  (:action pour_u46
    ; unit 46: pour from 05-french_toast.foon:175
    ; pour: plate (contains {french toast}), french toast (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {french toast, maple syrup}), french toast (cooked, on [plate], topped {maple syrup}), maple syrup (on [french toast])
    :parameters (?plate - plate ?french_toast - french_toast ?maple_syrup_portion - maple_syrup)
    :precondition (and
      (is ?plate plate_contains_french_toast)
      (is ?french_toast french_toast_cooked_on_plate)
      (on ?plate ?french_toast)
      (is ?maple_syrup_portion not-yet-made)
      (occupied maple_syrup_in_bottle)
    )
    :effect (and
      (is ?plate plate_contains_french_toast_maple_syrup)
      (occupied plate_contains_french_toast_maple_syrup)
      (is ?french_toast french_toast_cooked_on_plate_topped_maple_syrup)
      (occupied french_toast_cooked_on_plate_topped_maple_syrup)
      (is ?maple_syrup_portion maple_syrup_on_french_toast)
      (occupied maple_syrup_on_french_toast)
      (on ?french_toast ?maple_syrup_portion)
      (not (is ?plate plate_contains_french_toast))
      (not (is ?french_toast french_toast_cooked_on_plate))
      (not (is ?maple_syrup_portion not-yet-made))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: french toast (cooked, on [plate], topped {maple syrup})
    :parameters ()
    :precondition (and
      (occupied french_toast_cooked_on_plate_topped_maple_syrup)
    )
    :effect (and
      (goal-reached)
    )
  )
)
