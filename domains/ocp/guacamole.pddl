; foon2pddl, encoding ocp, level 3: 21 of 101 units after relevance pruning
; goal: guacamole (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-919064bd)
  (:requirements :strips)
  (:constants
    air
    avocado
    black_pepper
    bowl
    cilantro
    cutting_board
    fork
    guacamole
    juicer
    knife
    lime
    lime_juice
    onion
    salt
    spoon
    table
    tomato
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
    (is-chopped ?o)  ; ?o is chopped
    (is-ground ?o)  ; ?o is ground
    (is-sliced ?o)  ; ?o is sliced
    (is-whole ?o)  ; ?o is whole
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

  (:action pick-and-place_onion_47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole onion)
      (under onion table)
      (on table onion)
    )
    :effect (and
      (on cutting_board onion)
      (under onion cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole onion)
      (not (on cutting_board air))
    )
  )

  (:action chop_onion_49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-chopped onion)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_tomato_50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole tomato)
      (under tomato table)
      (on table tomato)
    )
    :effect (and
      (on cutting_board tomato)
      (under tomato cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole tomato)
      (not (on cutting_board air))
    )
  )

  (:action chop_tomato_51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board tomato)
      (under tomato cutting_board)
      (is-whole tomato)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-chopped tomato)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board tomato)
      (under tomato cutting_board)
      (under knife table)
      (on table knife)
      (not (is-whole tomato))
    )
  )

  (:action pick-and-place_avocado_63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole avocado)
      (under avocado table)
      (on table avocado)
    )
    :effect (and
      (on cutting_board avocado)
      (under avocado cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole avocado)
      (not (on cutting_board air))
    )
  )

  (:action scoop_avocado_65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (on cutting_board avocado)
      (under avocado cutting_board)
      (under spoon table)
      (on table spoon)
      (in bowl air)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl avocado)
      (under avocado bowl)
      (on cutting_board avocado)
      (under spoon table)
      (on table spoon)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )

  (:action pick-and-place_lime_67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole lime)
      (under lime table)
      (on table lime)
    )
    :effect (and
      (on cutting_board lime)
      (under lime cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole lime)
      (not (on cutting_board air))
    )
  )

  (:action squeeze_69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (on cutting_board lime)
      (under lime cutting_board)
      (in juicer air)
      (under juicer table)
      (on table juicer)
    )
    :effect (and
      (under lime table)
      (on table lime)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (on cutting_board lime)
      (under juicer table)
      (on table juicer)
      (not (in juicer air))
    )
  )

  (:action pour_lime_juice_70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (under juicer table)
      (on table juicer)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (under bowl table)
      (on table bowl)
      (in bowl avocado)
      (under avocado bowl)
    )
    :effect (and
      (in bowl lime_juice)
      (under lime_juice bowl)
      (under juicer table)
      (in juicer lime_juice)
      (under avocado bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action pick-and-place_onion_71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-chopped onion)
      (on cutting_board onion)
      (under onion cutting_board)
    )
    :effect (and
      (in bowl onion)
      (under onion bowl)
      (on cutting_board onion)
      (under bowl table)
      (on table bowl)
      (is-chopped onion)
    )
  )

  (:action pick-and-place_tomato_72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-chopped tomato)
      (on cutting_board tomato)
      (under tomato cutting_board)
    )
    :effect (and
      (in bowl tomato)
      (under tomato bowl)
      (on cutting_board tomato)
      (under bowl table)
      (on table bowl)
      (is-chopped tomato)
    )
  )

  (:action pick-and-place_cilantro_73
    ; unit 73: pick-and-place from 07-guacamole.foon:193
    ; pick-and-place: cutting board (empty), cilantro (fresh) -> cutting board (contains {cilantro}), cilantro (fresh, on [cutting board])
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (under cilantro table)
      (on table cilantro)
    )
    :effect (and
      (on cutting_board cilantro)
      (under cilantro cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (not (on cutting_board air))
    )
  )

  (:action chop_cilantro_74
    ; unit 74: chop from 07-guacamole.foon:204
    ; chop: cutting board (contains {cilantro}), cilantro (fresh, on [cutting board]), knife -> cutting board (contains {cilantro}), cilantro (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board cilantro)
      (under cilantro cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-chopped cilantro)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board cilantro)
      (under cilantro cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_cilantro_75
    ; unit 75: pick-and-place from 07-guacamole.foon:218
    ; pick-and-place: bowl (contains {avocado, lime juice, onion, tomato}), cilantro (chopped, on [cutting board]) -> bowl (contains {avocado, cilantro, lime juice, onion, tomato}), cilantro (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-chopped cilantro)
      (on cutting_board cilantro)
      (under cilantro cutting_board)
    )
    :effect (and
      (in bowl cilantro)
      (under cilantro bowl)
      (on cutting_board cilantro)
      (under bowl table)
      (on table bowl)
      (is-chopped cilantro)
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

  (:action mix_ingredients_77
    ; unit 77: mix from 07-guacamole.foon:240
    ; mix: bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), avocado (in [bowl], mashed), lime juice (in [bowl]), onion (chopped, in [bowl]), tomato (chopped, in [bowl]), cilantro (chopped, in [bowl]), salt (in [bowl]), for...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl avocado)
      (under avocado bowl)
      (in bowl lime_juice)
      (under lime_juice bowl)
      (is-chopped onion)
      (in bowl onion)
      (under onion bowl)
      (is-chopped tomato)
      (in bowl tomato)
      (under tomato bowl)
      (is-chopped cilantro)
      (in bowl cilantro)
      (under cilantro bowl)
      (in bowl salt)
      (under salt bowl)
      (under fork table)
      (on table fork)
    )
    :effect (and
      (in bowl guacamole)
      (under guacamole bowl)
      (under avocado bowl)
      (under lime_juice bowl)
      (is-chopped onion)
      (under onion bowl)
      (is-chopped tomato)
      (under tomato bowl)
      (is-chopped cilantro)
      (under cilantro bowl)
      (under salt bowl)
      (under bowl table)
      (on table bowl)
      (under fork table)
      (on table fork)
    )
  )

  (:action slice_onion_80
    ; unit 80: slice from 08-greek_salad.foon:78
    ; slice: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-sliced onion)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_tomato_82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-chopped tomato)
      (on cutting_board tomato)
      (under tomato cutting_board)
    )
    :effect (and
      (in bowl tomato)
      (under tomato bowl)
      (on cutting_board tomato)
      (under bowl table)
      (on table bowl)
      (is-chopped tomato)
    )
  )

  (:action pick-and-place_onion_83
    ; unit 83: pick-and-place from 08-greek_salad.foon:116
    ; pick-and-place: bowl (contains {cucumber, tomato}), onion (on [cutting board], sliced) -> bowl (contains {cucumber, onion, tomato}), onion (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (on cutting_board onion)
      (under onion cutting_board)
      (is-sliced onion)
    )
    :effect (and
      (in bowl onion)
      (under onion bowl)
      (on cutting_board onion)
      (under bowl table)
      (on table bowl)
      (is-sliced onion)
    )
  )

  (:action pour_lime_juice_96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (under juicer table)
      (on table juicer)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl lime_juice)
      (under lime_juice bowl)
      (under juicer table)
      (in juicer lime_juice)
      (under bowl table)
      (on table bowl)
    )
  )
)
