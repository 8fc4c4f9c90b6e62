; foon2pddl, encoding instances, level 3: 14 of 101 units after relevance pruning
; goal: french toast (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 15 (bowl 1, bread 1, butter 1, cinnamon 1, custard 1, egg 1, fork 1, french toast 1, frying pan 1, maple syrup 1, milk 1, plate 1, spatula 1, stove 1, vanilla extract 1)
; lanes: each instance changes state only as in the unfolded plan
; subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)
(define (domain foon-instances-373cb431)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
  )
  (:constants
    not-yet-made - object-state
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
    cinnamon_ground - object-state
    cinnamon_in_bowl - object-state
    custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl - object-state
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
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
    (lane ?x - physical-object ?s - object-state ?t - object-state)  ; static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)
    (together ?a - physical-object ?b - physical-object)  ; static: ?a and ?b change state in one firing of the unfolded plan
    (type_bowl ?x - physical-object)  ; ?x is of type bowl
    (type_bread ?x - physical-object)  ; ?x is of type bread
    (type_butter ?x - physical-object)  ; ?x is of type butter
    (type_cinnamon ?x - physical-object)  ; ?x is of type cinnamon
    (type_custard ?x - physical-object)  ; ?x is of type custard
    (type_egg ?x - physical-object)  ; ?x is of type egg
    (type_fork ?x - physical-object)  ; ?x is of type fork
    (type_french_toast ?x - physical-object)  ; ?x is of type french_toast
    (type_frying_pan ?x - physical-object)  ; ?x is of type frying_pan
    (type_maple_syrup ?x - physical-object)  ; ?x is of type maple_syrup
    (type_milk ?x - physical-object)  ; ?x is of type milk
    (type_plate ?x - physical-object)  ; ?x is of type plate
    (type_spatula ?x - physical-object)  ; ?x is of type spatula
    (type_stove ?x - physical-object)  ; ?x is of type stove
    (type_vanilla_extract ?x - physical-object)  ; ?x is of type vanilla_extract
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

  (:action pour_u40
    ; unit 40: pour* from 05-french_toast.foon:37
    ; pour: bowl (contains {egg, milk}), cinnamon (ground), vanilla extract (liquid) -> bowl (contains {cinnamon, egg, milk, vanilla extract}), cinnamon (in [bowl]), vanilla extract (in [bowl])
    :parameters (?bowl - physical-object ?cinnamon - physical-object ?vanilla_extract - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_cinnamon ?cinnamon)
      (type_vanilla_extract ?vanilla_extract)
      (together ?bowl ?cinnamon)
      (together ?cinnamon ?vanilla_extract)
      (is ?bowl bowl_contains_egg_milk)
      (lane ?bowl bowl_contains_egg_milk bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (is ?cinnamon cinnamon_ground)
      (lane ?cinnamon cinnamon_ground cinnamon_in_bowl)
      (is ?vanilla_extract vanilla_extract_liquid)
      (lane ?vanilla_extract vanilla_extract_liquid vanilla_extract_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (is ?cinnamon cinnamon_in_bowl)
      (occupied cinnamon_in_bowl)
      (is ?vanilla_extract vanilla_extract_in_bowl)
      (occupied vanilla_extract_in_bowl)
      (not (is ?bowl bowl_contains_egg_milk))
      (not (is ?cinnamon cinnamon_ground))
      (not (is ?vanilla_extract vanilla_extract_liquid))
    )
  )

  (:action mix_u41
    ; unit 41: mix from 05-french_toast.foon:51
    ; mix: bowl (contains {cinnamon, egg, milk, vanilla extract}), egg (beaten, in [bowl]), milk (in [bowl]), cinnamon (in [bowl]), vanilla extract (in [bowl]), fork -> bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla...
    :parameters (?bowl - physical-object ?custard - physical-object)
    :precondition (and
      (type_bowl ?bowl)
      (type_custard ?custard)
      (together ?bowl ?custard)
      (is ?bowl bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (lane ?bowl bowl_contains_cinnamon_egg_milk_vanilla_extract bowl_contains_custard)
      (occupied egg_beaten_in_bowl)
      (occupied milk_in_bowl)
      (occupied cinnamon_in_bowl)
      (occupied vanilla_extract_in_bowl)
      (occupied fork_plain)
      (is ?custard not-yet-made)
      (lane ?custard not-yet-made custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
    )
    :effect (and
      (is ?bowl bowl_contains_custard)
      (occupied bowl_contains_custard)
      (is ?custard custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
      (occupied custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
      (not (is ?bowl bowl_contains_cinnamon_egg_milk_vanilla_extract))
      (not (is ?custard not-yet-made))
    )
  )

  (:action dip_u42
    ; unit 42: dip from 05-french_toast.foon:71
    ; dip: bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla extract}, in [bowl]), bread (sliced) -> bread (sliced, soaked {custard})
    :parameters (?bread - physical-object)
    :precondition (and
      (type_bread ?bread)
      (occupied bowl_contains_custard)
      (occupied custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
      (is ?bread bread_sliced)
      (lane ?bread bread_sliced bread_sliced_soaked_custard)
    )
    :effect (and
      (is ?bread bread_sliced_soaked_custard)
      (not (is ?bread bread_sliced))
    )
  )

  (:action pick-and-place_u43
    ; unit 43: pick-and-place from 05-french_toast.foon:121
    ; pick-and-place: frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted), bread (sliced, soaked {custard}) -> frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard})
    :parameters (?frying_pan - physical-object ?bread - physical-object)
    :precondition (and
      (type_frying_pan ?frying_pan)
      (type_bread ?bread)
      (together ?frying_pan ?bread)
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (lane ?frying_pan frying_pan_contains_butter_on_stove frying_pan_contains_bread_butter_on_stove)
      (occupied butter_in_frying_pan_melted)
      (is ?bread bread_sliced_soaked_custard)
      (lane ?bread bread_sliced_soaked_custard bread_in_frying_pan_sliced_soaked_custard)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_bread_butter_on_stove)
      (is ?bread bread_in_frying_pan_sliced_soaked_custard)
      (occupied bread_in_frying_pan_sliced_soaked_custard)
      (not (is ?frying_pan frying_pan_contains_butter_on_stove))
      (not (is ?bread bread_sliced_soaked_custard))
    )
  )

  (:action fry_u44
    ; unit 44: fry from 05-french_toast.foon:139
    ; fry: stove (on), frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard}), spatula -> frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula
    :parameters (?frying_pan - physical-object ?french_toast - physical-object)
    :precondition (and
      (type_frying_pan ?frying_pan)
      (type_french_toast ?french_toast)
      (together ?frying_pan ?french_toast)
      (occupied stove_on)
      (is ?frying_pan frying_pan_contains_bread_butter_on_stove)
      (lane ?frying_pan frying_pan_contains_bread_butter_on_stove frying_pan_contains_french_toast_on_stove)
      (occupied bread_in_frying_pan_sliced_soaked_custard)
      (occupied spatula_plain)
      (is ?french_toast not-yet-made)
      (lane ?french_toast not-yet-made french_toast_cooked_in_frying_pan)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_french_toast_on_stove)
      (occupied frying_pan_contains_french_toast_on_stove)
      (is ?french_toast french_toast_cooked_in_frying_pan)
      (not (is ?frying_pan frying_pan_contains_bread_butter_on_stove))
      (not (is ?french_toast not-yet-made))
    )
  )

  (:action pick-and-place_u45
    ; unit 45: pick-and-place from 05-french_toast.foon:158
    ; pick-and-place: frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {french toast}), french toast (cooked, on [plate]), spatula
    :parameters (?french_toast - physical-object ?plate - physical-object)
    :precondition (and
      (type_french_toast ?french_toast)
      (type_plate ?plate)
      (together ?french_toast ?plate)
      (occupied frying_pan_contains_french_toast_on_stove)
      (is ?french_toast french_toast_cooked_in_frying_pan)
      (lane ?french_toast french_toast_cooked_in_frying_pan french_toast_cooked_on_plate)
      (occupied spatula_plain)
      (is ?plate plate_empty)
      (lane ?plate plate_empty plate_contains_french_toast)
    )
    :effect (and
      (is ?french_toast french_toast_cooked_on_plate)
      (is ?plate plate_contains_french_toast)
      (not (is ?french_toast french_toast_cooked_in_frying_pan))
      (not (is ?plate plate_empty))
    )
  )

  (:action pour_u46
    ; unit 46: pour from 05-french_toast.foon:175
    ; pour: plate (contains {french toast}), french toast (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {french toast, maple syrup}), french toast (cooked, on [plate], topped {maple syrup}), maple syrup (on [french toast])
    :parameters (?plate - physical-object ?french_toast - physical-object ?maple_syrup - physical-object)
    :precondition (and
      (type_plate ?plate)
      (type_french_toast ?french_toast)
      (type_maple_syrup ?maple_syrup)
      (together ?plate ?french_toast)
      (together ?french_toast ?maple_syrup)
      (is ?plate plate_contains_french_toast)
      (lane ?plate plate_contains_french_toast plate_contains_french_toast_maple_syrup)
      (is ?french_toast french_toast_cooked_on_plate)
      (lane ?french_toast french_toast_cooked_on_plate french_toast_cooked_on_plate_topped_maple_syrup)
      (is ?maple_syrup maple_syrup_in_bottle)
      (lane ?maple_syrup maple_syrup_in_bottle maple_syrup_on_french_toast)
    )
    :effect (and
      (is ?plate plate_contains_french_toast_maple_syrup)
      (occupied plate_contains_french_toast_maple_syrup)
      (is ?french_toast french_toast_cooked_on_plate_topped_maple_syrup)
      (occupied french_toast_cooked_on_plate_topped_maple_syrup)
      (is ?maple_syrup maple_syrup_on_french_toast)
      (occupied maple_syrup_on_french_toast)
      (not (is ?plate plate_contains_french_toast))
      (not (is ?french_toast french_toast_cooked_on_plate))
      (not (is ?maple_syrup maple_syrup_in_bottle))
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
