; foon2pddl, encoding relational, level 3: 22 of 101 units after relevance pruning
; goal: guacamole (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 18 (avocado 1, bowl 1, cilantro 1, cutting board 5, fork 1, guacamole 1, juicer 1, knife 1, lime 1, lime juice 1, onion 1, salt 1, spoon 1, tomato 1)
; objects: 5 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, pick-and-place at 07-guacamole.foon:3, pick-and-place at 07-guacamole.foon:52, ... (1 more), and no unit puts one back
(define (domain foon-relational-71e09b19)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    avocado - physical-object
    bowl - physical-object
    cilantro - physical-object
    cutting_board - physical-object
    fork - physical-object
    guacamole - physical-object
    juicer - physical-object
    knife - physical-object
    lime - physical-object
    lime_juice - physical-object
    onion - physical-object
    salt - physical-object
    spoon - physical-object
    tomato - physical-object
  )
  (:constants
    not-yet-made - object-state
    consumed - object-state
    avocado_halved_on_cutting_board - object-state
    avocado_in_bowl_mashed - object-state
    avocado_in_bowl_scooped - object-state
    avocado_on_cutting_board_whole - object-state
    avocado_whole - object-state
    bowl_contains_avocado - object-state
    bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato - object-state
    bowl_contains_avocado_cilantro_lime_juice_onion_tomato - object-state
    bowl_contains_avocado_lime_juice - object-state
    bowl_contains_avocado_lime_juice_onion - object-state
    bowl_contains_avocado_lime_juice_onion_tomato - object-state
    bowl_contains_banana_lime_juice_strawberry - object-state
    bowl_contains_banana_strawberry - object-state
    bowl_contains_cucumber - object-state
    bowl_contains_cucumber_tomato - object-state
    bowl_contains_guacamole - object-state
    bowl_empty - object-state
    cilantro_chopped_in_bowl - object-state
    cilantro_chopped_on_cutting_board - object-state
    cilantro_fresh - object-state
    cilantro_fresh_on_cutting_board - object-state
    cutting_board_contains_avocado - object-state
    cutting_board_contains_cilantro - object-state
    cutting_board_contains_lime - object-state
    cutting_board_contains_onion - object-state
    cutting_board_contains_tomato - object-state
    cutting_board_empty - object-state
    fork_plain - object-state
    guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl - object-state
    juicer_contains_lime_juice - object-state
    juicer_empty - object-state
    knife_plain - object-state
    lime_halved_on_cutting_board - object-state
    lime_on_cutting_board_whole - object-state
    lime_squeezed - object-state
    lime_whole - object-state
    lime_juice_in_bowl - object-state
    lime_juice_in_juicer - object-state
    onion_chopped_in_bowl - object-state
    onion_chopped_on_cutting_board - object-state
    onion_on_cutting_board_peeled - object-state
    onion_on_cutting_board_whole - object-state
    onion_whole - object-state
    salt_granulated - object-state
    salt_in_bowl - object-state
    spoon_plain - object-state
    tomato_chopped_in_bowl - object-state
    tomato_chopped_on_cutting_board - object-state
    tomato_on_cutting_board_whole - object-state
    tomato_whole - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (in ?h - physical-object ?x - physical-object)  ; ?x is in ?h
    (on ?h - physical-object ?x - physical-object)  ; ?x is on ?h
    (occupied ?s - object-state)  ; some object is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?onion - onion)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?onion onion_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_whole)
      (on ?cutting_board ?onion)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?onion onion_whole))
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters (?cutting_board - cutting_board ?onion - onion)
    :precondition (and
      (is ?cutting_board cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_whole)
      (on ?cutting_board ?onion)
      (occupied knife_plain)
    )
    :effect (and
      (is ?onion onion_on_cutting_board_peeled)
      (not (is ?onion onion_on_cutting_board_whole))
    )
  )

  (:action chop_u49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters (?cutting_board - cutting_board ?onion - onion)
    :precondition (and
      (is ?cutting_board cutting_board_contains_onion)
      (is ?onion onion_on_cutting_board_peeled)
      (on ?cutting_board ?onion)
      (occupied knife_plain)
    )
    :effect (and
      (is ?onion onion_chopped_on_cutting_board)
      (not (is ?onion onion_on_cutting_board_peeled))
    )
  )

  (:action pick-and-place_u50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?tomato - tomato)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?tomato tomato_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_tomato)
      (is ?tomato tomato_on_cutting_board_whole)
      (on ?cutting_board ?tomato)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?tomato tomato_whole))
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters (?cutting_board - cutting_board ?tomato - tomato)
    :precondition (and
      (is ?cutting_board cutting_board_contains_tomato)
      (is ?tomato tomato_on_cutting_board_whole)
      (on ?cutting_board ?tomato)
      (occupied knife_plain)
    )
    :effect (and
      (is ?tomato tomato_chopped_on_cutting_board)
      (not (is ?tomato tomato_on_cutting_board_whole))
    )
  )

  (:action pick-and-place_u63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?avocado - avocado)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?avocado avocado_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_avocado)
      (is ?avocado avocado_on_cutting_board_whole)
      (on ?cutting_board ?avocado)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?avocado avocado_whole))
    )
  )

  (:action cut_u64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters (?cutting_board - cutting_board ?avocado - avocado)
    :precondition (and
      (is ?cutting_board cutting_board_contains_avocado)
      (is ?avocado avocado_on_cutting_board_whole)
      (on ?cutting_board ?avocado)
      (occupied knife_plain)
    )
    :effect (and
      (is ?avocado avocado_halved_on_cutting_board)
      (not (is ?avocado avocado_on_cutting_board_whole))
    )
  )

  (:action scoop_u65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters (?avocado - avocado ?bowl - bowl)
    :precondition (and
      (is ?avocado avocado_halved_on_cutting_board)
      (occupied spoon_plain)
      (is ?bowl bowl_empty)
    )
    :effect (and
      (is ?avocado avocado_in_bowl_scooped)
      (in ?bowl ?avocado)
      (is ?bowl bowl_contains_avocado)
      (not (is ?avocado avocado_halved_on_cutting_board))
      (not (is ?bowl bowl_empty))
      (forall (?from_0 - physical-object) (when (on ?from_0 ?avocado) (not (on ?from_0 ?avocado))))
      (forall (?from_0 - physical-object) (when (and (on ?from_0 ?avocado) (is ?from_0 cutting_board_contains_avocado)) (and (is ?from_0 cutting_board_empty) (not (is ?from_0 cutting_board_contains_avocado)))))
    )
  )

  (:action mash_u66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters (?avocado - avocado)
    :precondition (and
      (is ?avocado avocado_in_bowl_scooped)
      (occupied fork_plain)
    )
    :effect (and
      (is ?avocado avocado_in_bowl_mashed)
      (not (is ?avocado avocado_in_bowl_scooped))
    )
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?lime - lime)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?lime lime_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_lime)
      (is ?lime lime_on_cutting_board_whole)
      (on ?cutting_board ?lime)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?lime lime_whole))
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters (?cutting_board - cutting_board ?lime - lime)
    :precondition (and
      (is ?cutting_board cutting_board_contains_lime)
      (is ?lime lime_on_cutting_board_whole)
      (on ?cutting_board ?lime)
      (occupied knife_plain)
    )
    :effect (and
      (is ?lime lime_halved_on_cutting_board)
      (not (is ?lime lime_on_cutting_board_whole))
    )
  )

  (:action squeeze_u69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters (?lime - lime ?juicer - juicer ?lime_juice - lime_juice)
    :precondition (and
      (is ?lime lime_halved_on_cutting_board)
      (is ?juicer juicer_empty)
      (is ?lime_juice not-yet-made)
    )
    :effect (and
      (is ?lime lime_squeezed)
      (occupied lime_squeezed)
      (is ?juicer juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (in ?juicer ?lime_juice)
      (not (is ?lime lime_halved_on_cutting_board))
      (not (is ?juicer juicer_empty))
      (not (is ?lime_juice not-yet-made))
      (forall (?from_0 - physical-object) (when (on ?from_0 ?lime) (not (on ?from_0 ?lime))))
      (forall (?from_0 - physical-object) (when (and (on ?from_0 ?lime) (is ?from_0 cutting_board_contains_lime)) (and (is ?from_0 cutting_board_empty) (not (is ?from_0 cutting_board_contains_lime)))))
    )
  )

  (:action pour_u70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters (?juicer - juicer ?lime_juice - lime_juice ?bowl - bowl ?avocado - avocado)
    :precondition (and
      (is ?juicer juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (in ?juicer ?lime_juice)
      (is ?bowl bowl_contains_avocado)
      (is ?avocado avocado_in_bowl_mashed)
      (in ?bowl ?avocado)
    )
    :effect (and
      (is ?juicer juicer_empty)
      (is ?lime_juice lime_juice_in_bowl)
      (in ?bowl ?lime_juice)
      (is ?bowl bowl_contains_avocado_lime_juice)
      (not (is ?juicer juicer_contains_lime_juice))
      (not (is ?lime_juice lime_juice_in_juicer))
      (not (in ?juicer ?lime_juice))
      (not (is ?bowl bowl_contains_avocado))
    )
  )

  (:action pick-and-place_u71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters (?bowl - bowl ?onion - onion)
    :precondition (and
      (is ?bowl bowl_contains_avocado_lime_juice)
      (is ?onion onion_chopped_on_cutting_board)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion)
      (is ?onion onion_chopped_in_bowl)
      (in ?bowl ?onion)
      (not (is ?bowl bowl_contains_avocado_lime_juice))
      (not (is ?onion onion_chopped_on_cutting_board))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?onion) (not (on ?from_1 ?onion))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?onion) (is ?from_1 cutting_board_contains_onion)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_onion)))))
    )
  )

  (:action pick-and-place_u72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters (?bowl - bowl ?tomato - tomato)
    :precondition (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion)
      (is ?tomato tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion_tomato)
      (is ?tomato tomato_chopped_in_bowl)
      (in ?bowl ?tomato)
      (not (is ?bowl bowl_contains_avocado_lime_juice_onion))
      (not (is ?tomato tomato_chopped_on_cutting_board))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?tomato) (not (on ?from_1 ?tomato))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?tomato) (is ?from_1 cutting_board_contains_tomato)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_tomato)))))
    )
  )

  (:action pick-and-place_u73
    ; unit 73: pick-and-place from 07-guacamole.foon:193
    ; pick-and-place: cutting board (empty), cilantro (fresh) -> cutting board (contains {cilantro}), cilantro (fresh, on [cutting board])
    :parameters (?cutting_board - cutting_board ?cilantro - cilantro)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?cilantro cilantro_fresh)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_cilantro)
      (is ?cilantro cilantro_fresh_on_cutting_board)
      (on ?cutting_board ?cilantro)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?cilantro cilantro_fresh))
    )
  )

  (:action chop_u74
    ; unit 74: chop from 07-guacamole.foon:204
    ; chop: cutting board (contains {cilantro}), cilantro (fresh, on [cutting board]), knife -> cutting board (contains {cilantro}), cilantro (chopped, on [cutting board]), knife
    :parameters (?cutting_board - cutting_board ?cilantro - cilantro)
    :precondition (and
      (is ?cutting_board cutting_board_contains_cilantro)
      (is ?cilantro cilantro_fresh_on_cutting_board)
      (on ?cutting_board ?cilantro)
      (occupied knife_plain)
    )
    :effect (and
      (is ?cilantro cilantro_chopped_on_cutting_board)
      (not (is ?cilantro cilantro_fresh_on_cutting_board))
    )
  )

  (:action pick-and-place_u75
    ; unit 75: pick-and-place from 07-guacamole.foon:218
    ; pick-and-place: bowl (contains {avocado, lime juice, onion, tomato}), cilantro (chopped, on [cutting board]) -> bowl (contains {avocado, cilantro, lime juice, onion, tomato}), cilantro (chopped, in [bowl])
    :parameters (?bowl - bowl ?cilantro - cilantro)
    :precondition (and
      (is ?bowl bowl_contains_avocado_lime_juice_onion_tomato)
      (is ?cilantro cilantro_chopped_on_cutting_board)
    )
    :effect (and
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (is ?cilantro cilantro_chopped_in_bowl)
      (in ?bowl ?cilantro)
      (not (is ?bowl bowl_contains_avocado_lime_juice_onion_tomato))
      (not (is ?cilantro cilantro_chopped_on_cutting_board))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?cilantro) (not (on ?from_1 ?cilantro))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?cilantro) (is ?from_1 cutting_board_contains_cilantro)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_cilantro)))))
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
      (is ?salt salt_in_bowl)
      (in ?bowl ?salt)
      (not (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_tomato))
      (not (is ?salt salt_granulated))
    )
  )

  (:action mix_u77
    ; unit 77: mix from 07-guacamole.foon:240
    ; mix: bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), avocado (in [bowl], mashed), lime juice (in [bowl]), onion (chopped, in [bowl]), tomato (chopped, in [bowl]), cilantro (chopped, in [bowl]), salt (in [bowl]), for...
    :parameters (?bowl - bowl ?avocado - avocado ?lime_juice - lime_juice ?onion - onion ?tomato - tomato ?cilantro - cilantro ?salt - salt ?guacamole - guacamole)
    :precondition (and
      (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is ?avocado avocado_in_bowl_mashed)
      (in ?bowl ?avocado)
      (is ?lime_juice lime_juice_in_bowl)
      (in ?bowl ?lime_juice)
      (is ?onion onion_chopped_in_bowl)
      (in ?bowl ?onion)
      (is ?tomato tomato_chopped_in_bowl)
      (in ?bowl ?tomato)
      (is ?cilantro cilantro_chopped_in_bowl)
      (in ?bowl ?cilantro)
      (is ?salt salt_in_bowl)
      (in ?bowl ?salt)
      (occupied fork_plain)
      (is ?guacamole not-yet-made)
    )
    :effect (and
      (is ?bowl bowl_contains_guacamole)
      (occupied bowl_contains_guacamole)
      (is ?avocado consumed)
      (is ?lime_juice consumed)
      (is ?onion consumed)
      (is ?tomato consumed)
      (is ?cilantro consumed)
      (is ?salt consumed)
      (is ?guacamole guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl)
      (occupied guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl)
      (in ?bowl ?guacamole)
      (not (is ?bowl bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato))
      (not (is ?avocado avocado_in_bowl_mashed))
      (not (in ?bowl ?avocado))
      (not (is ?lime_juice lime_juice_in_bowl))
      (not (in ?bowl ?lime_juice))
      (not (is ?onion onion_chopped_in_bowl))
      (not (in ?bowl ?onion))
      (not (is ?tomato tomato_chopped_in_bowl))
      (not (in ?bowl ?tomato))
      (not (is ?cilantro cilantro_chopped_in_bowl))
      (not (in ?bowl ?cilantro))
      (not (is ?salt salt_in_bowl))
      (not (in ?bowl ?salt))
      (not (is ?guacamole not-yet-made))
      (forall (?avocado_alike - avocado) (when (and (in ?bowl ?avocado_alike) (is ?avocado_alike avocado_in_bowl_mashed)) (and (is ?avocado_alike consumed) (not (in ?bowl ?avocado_alike)) (not (is ?avocado_alike avocado_in_bowl_mashed)))))
      (forall (?avocado_alike-2 - avocado) (when (and (in ?bowl ?avocado_alike-2) (is ?avocado_alike-2 avocado_in_bowl_scooped)) (and (is ?avocado_alike-2 consumed) (not (in ?bowl ?avocado_alike-2)) (not (is ?avocado_alike-2 avocado_in_bowl_scooped)))))
      (forall (?lime_juice_alike - lime_juice) (when (and (in ?bowl ?lime_juice_alike) (is ?lime_juice_alike lime_juice_in_bowl)) (and (is ?lime_juice_alike consumed) (not (in ?bowl ?lime_juice_alike)) (not (is ?lime_juice_alike lime_juice_in_bowl)))))
      (forall (?onion_alike - onion) (when (and (in ?bowl ?onion_alike) (is ?onion_alike onion_chopped_in_bowl)) (and (is ?onion_alike consumed) (not (in ?bowl ?onion_alike)) (not (is ?onion_alike onion_chopped_in_bowl)))))
      (forall (?tomato_alike - tomato) (when (and (in ?bowl ?tomato_alike) (is ?tomato_alike tomato_chopped_in_bowl)) (and (is ?tomato_alike consumed) (not (in ?bowl ?tomato_alike)) (not (is ?tomato_alike tomato_chopped_in_bowl)))))
      (forall (?cilantro_alike - cilantro) (when (and (in ?bowl ?cilantro_alike) (is ?cilantro_alike cilantro_chopped_in_bowl)) (and (is ?cilantro_alike consumed) (not (in ?bowl ?cilantro_alike)) (not (is ?cilantro_alike cilantro_chopped_in_bowl)))))
      (forall (?salt_alike - salt) (when (and (in ?bowl ?salt_alike) (is ?salt_alike salt_in_bowl)) (and (is ?salt_alike consumed) (not (in ?bowl ?salt_alike)) (not (is ?salt_alike salt_in_bowl)))))
    )
  )

  (:action pick-and-place_u82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters (?bowl - bowl ?tomato - tomato)
    :precondition (and
      (is ?bowl bowl_contains_cucumber)
      (is ?tomato tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is ?bowl bowl_contains_cucumber_tomato)
      (occupied bowl_contains_cucumber_tomato)
      (is ?tomato tomato_chopped_in_bowl)
      (in ?bowl ?tomato)
      (not (is ?bowl bowl_contains_cucumber))
      (not (is ?tomato tomato_chopped_on_cutting_board))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?tomato) (not (on ?from_1 ?tomato))))
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?tomato) (is ?from_1 cutting_board_contains_tomato)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_tomato)))))
    )
  )

  (:action pour_u96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters (?juicer - juicer ?lime_juice - lime_juice ?bowl - bowl)
    :precondition (and
      (is ?juicer juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (in ?juicer ?lime_juice)
      (is ?bowl bowl_contains_banana_strawberry)
    )
    :effect (and
      (is ?juicer juicer_empty)
      (is ?lime_juice lime_juice_in_bowl)
      (in ?bowl ?lime_juice)
      (is ?bowl bowl_contains_banana_lime_juice_strawberry)
      (occupied bowl_contains_banana_lime_juice_strawberry)
      (not (is ?juicer juicer_contains_lime_juice))
      (not (is ?lime_juice lime_juice_in_juicer))
      (not (in ?juicer ?lime_juice))
      (not (is ?bowl bowl_contains_banana_strawberry))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: guacamole (contains {avocado, cilantro, lime juice, onion, salt, tomato}, in [bowl])
    :parameters ()
    :precondition (and
      (occupied guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl)
    )
    :effect (and
      (goal-reached)
    )
  )
)
