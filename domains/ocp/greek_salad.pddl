; foon2pddl, encoding ocp, level 3: 17 of 101 units after relevance pruning
; goal: greek salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-4076678c)
  (:requirements :strips)
  (:constants
    air
    black_olive
    bottle
    bowl
    cucumber
    cutting_board
    feta_cheese
    greek_salad
    knife
    olive_oil
    onion
    oregano
    red_wine_vinegar
    salad_tongs
    table
    tomato
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
    (is-chopped ?o)  ; ?o is chopped
    (is-sliced ?o)  ; ?o is sliced
    (is-whole ?o)  ; ?o is whole
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

  (:action pick-and-place_cucumber_78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole cucumber)
      (under cucumber table)
      (on table cucumber)
    )
    :effect (and
      (on cutting_board cucumber)
      (under cucumber cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole cucumber)
      (not (on cutting_board air))
    )
  )

  (:action slice_cucumber_79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board cucumber)
      (under cucumber cutting_board)
      (is-whole cucumber)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-sliced cucumber)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board cucumber)
      (under cucumber cutting_board)
      (under knife table)
      (on table knife)
      (not (is-whole cucumber))
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

  (:action pick-and-place_cucumber_81
    ; unit 81: pick-and-place from 08-greek_salad.foon:92
    ; pick-and-place: bowl (empty), cucumber (on [cutting board], sliced) -> bowl (contains {cucumber}), cucumber (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (in bowl air)
      (under bowl table)
      (on table bowl)
      (on cutting_board cucumber)
      (under cucumber cutting_board)
      (is-sliced cucumber)
    )
    :effect (and
      (in bowl cucumber)
      (under cucumber bowl)
      (on cutting_board cucumber)
      (under bowl table)
      (on table bowl)
      (is-sliced cucumber)
      (not (in bowl air))
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

  (:action pick-and-place_black_olive_84
    ; unit 84: pick-and-place from 08-greek_salad.foon:128
    ; pick-and-place: bowl (contains {cucumber, onion, tomato}), black olive (pitted) -> bowl (contains {black olive, cucumber, onion, tomato}), black olive (in [bowl], pitted)
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under black_olive table)
      (on table black_olive)
    )
    :effect (and
      (in bowl black_olive)
      (under black_olive bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action sprinkle_feta_cheese_85
    ; unit 85: sprinkle from 08-greek_salad.foon:139
    ; sprinkle: bowl (contains {black olive, cucumber, onion, tomato}), feta cheese (crumbled) -> bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), feta cheese (crumbled, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under feta_cheese table)
      (on table feta_cheese)
    )
    :effect (and
      (in bowl feta_cheese)
      (under feta_cheese bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action pour_olive_oil_86
    ; unit 86: pour* from 08-greek_salad.foon:150
    ; pour: bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), olive oil (in [bottle]), red wine vinegar (in [bottle]) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), olive...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bottle olive_oil)
      (under olive_oil bottle)
      (in bottle red_wine_vinegar)
      (under red_wine_vinegar bottle)
    )
    :effect (and
      (in bowl olive_oil)
      (under olive_oil bowl)
      (in bowl red_wine_vinegar)
      (under red_wine_vinegar bowl)
      (in bottle olive_oil)
      (in bottle red_wine_vinegar)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action sprinkle_oregano_87
    ; unit 87: sprinkle from 08-greek_salad.foon:164
    ; sprinkle: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), oregano (dried) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), ore...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under oregano table)
      (on table oregano)
    )
    :effect (and
      (in bowl oregano)
      (under oregano bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action toss_88
    ; unit 88: toss from 08-greek_salad.foon:174
    ; toss: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), cucumber (in [bowl], sliced), tomato (chopped, in [bowl]), onion (in [bowl], sliced), black olive (in [bowl], pitted), feta ...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl cucumber)
      (under cucumber bowl)
      (is-sliced cucumber)
      (is-chopped tomato)
      (in bowl tomato)
      (under tomato bowl)
      (in bowl onion)
      (under onion bowl)
      (is-sliced onion)
      (in bowl black_olive)
      (under black_olive bowl)
      (in bowl feta_cheese)
      (under feta_cheese bowl)
      (in bowl olive_oil)
      (under olive_oil bowl)
      (in bowl red_wine_vinegar)
      (under red_wine_vinegar bowl)
      (in bowl oregano)
      (under oregano bowl)
      (under salad_tongs table)
      (on table salad_tongs)
    )
    :effect (and
      (in bowl greek_salad)
      (under greek_salad bowl)
      (under cucumber bowl)
      (is-sliced cucumber)
      (is-chopped tomato)
      (under tomato bowl)
      (under onion bowl)
      (is-sliced onion)
      (under black_olive bowl)
      (under feta_cheese bowl)
      (under olive_oil bowl)
      (under red_wine_vinegar bowl)
      (under oregano bowl)
      (under bowl table)
      (on table bowl)
      (under salad_tongs table)
      (on table salad_tongs)
    )
  )
)
